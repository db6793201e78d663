#!/usr/bin/env python3
"""Runs the load-time benchmarks that issue 16's goals are about and prints
a markdown table of ratios: compile time over the parse floor per format,
growth per element from the small to the large size, worlds of many models,
nesting depth, peak memory over the DOM's, one-shot processes (mdlc compile
against xmllint, CPU time and memory as the kernel accounts them), and the
comparison with libsdformat and MuJoCo 2.2.2, and the XML formats' compiles
against libxml2's SAX events alone (handlers that do nothing: the part of
a compile that is libxml2's own). The benchmark binaries keep
freed memory for reuse (tools/driver/heap_policy.h), as the mdlc command
does; the one-shot rows pay every first touch.

    python3 tools/bench_table.py [BUILD_DIR] [--repetitions=3] [--rounds=5]
                                 [--readme=README.md] [--corpus=DIR] [--only-meshes]
                                 [--only-dynamics]

BUILD_DIR (default: build) must hold mdlc, mdlc_bench, mdlc_bench_sdf and
mdlc_bench_dmd. When it also holds mdlc_bench_meshes, a last part times
mesh-heavy models (issue 57): synthetic ones and real ones from the corpus
(--corpus, default $MDLC_CORPUS, else ../shared/corpus), the mesh cache cold
and warm, meshes read by child processes and in-process, and MuJoCo 2.2.2's
load of the same MJCF files, in wall time (the child readers' work is in
other processes); --only-meshes runs that part alone. --only-dynamics
runs mdlc_bench_dynamics alone (never part of the whole table: the README
keeps it in a section of its own): mdlc's inverse dynamics, mass matrix
and forward dynamics per call against MuJoCo 2.2.2's on the same MJCF
files. Ratios are paired: one process runs a family's floor and
compile at both sizes, --repetitions times each, interleaved at random, and
the family's ratios are read from that process's fastest CPU times; each
number in the table is the median over --rounds such processes. A slow
stretch of the machine, which can last minutes, then moves both sides of a
ratio alike. The fastest run, not the median, is read within a process:
there the parse floor's time depends on the heap its previous run left
behind (glibc consolidating millions of freed DOM nodes), and falls into
two modes, one about twice the other; the fastest run is the parse's own
cost, and mdlc's compile is read the same way. The
one-shot processes, fresh each time, use the median, over more runs for the
short ones (as many as fill about a second, up to ONE_SHOT_MAX_RUNS): a
process of 10 ms moves by a millisecond from run to run, as much as the
difference being measured. With --readme, the
table between the bench-table markers of that file is replaced as well.

Times move with the machine (other processes, a virtual machine's
neighbours, a kernel that pages out idle memory), so the table also counts
the work in instructions, with valgrind's callgrind where it is installed:
mdlc's compile against libxml2's parse and free of the same file, the same
on every run and every machine. --no-instructions skips that part. Takes
about ten minutes with the default rounds, and a few more with the
instruction counts.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

# the nested models are 10,000 deep, past the model-depth limit's default
MDLC_FLAGS = ["--emit=none", "--limit", "model-depth=100000"]

BEGIN = "<!-- bench-table:begin -->"
END = "<!-- bench-table:end -->"


# (label, family, floor benchmark, sizes, binary): each family's floor and
# compile at every size run in one process of their own, interleaved.
FAMILIES = [
    ("URDF chain", "chain", "libxml2_parse", (1000, 10000), "mdlc_bench"),
    ("URDF tree", "tree", "libxml2_parse", (1000, 10000), "mdlc_bench"),
    ("MJCF chain", "mjcf_chain", "libxml2_parse", (1000, 10000), "mdlc_bench"),
    ("MJCF tree", "mjcf_tree", "libxml2_parse", (1000, 10000), "mdlc_bench"),
    ("SDFormat chain", "sdf_chain", "libxml2_parse", (1000, 10000), "mdlc_bench_sdf"),
    ("SDFormat nested models (N deep)", "nested_models", "libxml2_parse", (1000, 10000),
     "mdlc_bench_sdf"),
    ("SDFormat world of N one-link models", "world", "libxml2_parse", (1000, 10000, 100000),
     "mdlc_bench_sdf"),
    ("Model Directives, N three-link arms", "dmd_chain", "yaml_parse", (100, 1000),
     "mdlc_bench_dmd"),
]
# (name, binary, the reference loader's benchmark, mdlc's compile of the same file)
REFERENCES = [
    ("mujoco", "mdlc_bench", "mujoco_load/mjcf_tree/1000", "compile/mjcf_tree/1000"),
    ("sdformat_chain", "mdlc_bench_sdf", "libsdformat_load/sdf_chain/1000",
     "compile/sdf_chain/1000"),
    ("sdformat_world", "mdlc_bench_sdf", "libsdformat_load/world/1000", "compile/world/1000"),
]


def benchmark_runs(exe, pattern, repetitions, min_time, extra_args=()):
    """The runs (Google Benchmark's JSON records) of the benchmarks matching
    `pattern`, --repetitions times each, interleaved at random; None when
    `exe` is not built."""
    if not os.path.exists(exe):
        print(f"bench_table: {exe} is not built; skipping it", file=sys.stderr)
        return None
    out = subprocess.run(
        [exe, f"--benchmark_filter={pattern}", f"--benchmark_repetitions={repetitions}",
         f"--benchmark_min_time={min_time}", "--benchmark_enable_random_interleaving=true",
         "--benchmark_format=json"] + list(extra_args),
        check=True, capture_output=True, text=True).stdout
    return json.loads(out)["benchmarks"]


def fastest_times(runs, key="cpu_time"):
    """{name: fastest `key` time in ms} over the runs that did not fail."""
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
    times = {}
    for b in runs or []:
        if b.get("run_type") != "iteration" or b.get("error_occurred"):
            continue
        t = b[key] * scale[b["time_unit"]]
        times[b["run_name"]] = min(t, times.get(b["run_name"], t))
    return times


def run_benchmarks(exe, pattern, repetitions, min_time):
    """{name: fastest cpu time in ms over the repetitions} for the benchmarks
    matching `pattern`."""
    return fastest_times(benchmark_runs(exe, pattern, repetitions, min_time))


def measure_process(command):
    """(CPU time in ms, user + system; peak resident memory in kB) of one run
    of `command`. It runs under GNU time, which reports the peak memory of the
    command alone (a child forked from this interpreter would count its pages
    too); the CPU time is the kernel's account of GNU time and its child
    (wait4), finer than GNU time's own centiseconds."""
    with open(os.devnull, "wb") as null:
        child = subprocess.Popen(["/usr/bin/time", "-f", "%M"] + command, stdout=null,
                                 stderr=subprocess.PIPE)
        stderr = child.stderr.read().decode(errors="replace")
        _, status, usage = os.wait4(child.pid, 0)
        child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed: {stderr[-500:]}")
    return (usage.ru_utime + usage.ru_stime) * 1000.0, int(stderr.strip().splitlines()[-1])


def count_instructions(command, functions):
    """Instructions one run of `command` executes inside `functions` (and what
    they call), as valgrind's callgrind counts them; None without valgrind.
    Each function toggles counting on entry and back on return, so a function
    named inside another one is left out of it."""
    with tempfile.TemporaryDirectory(prefix="mdlc_callgrind_") as d:
        result = subprocess.run(
            ["valgrind", "--tool=callgrind", f"--callgrind-out-file={d}/out"]
            + [f"--toggle-collect={f}" for f in functions] + command,
            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    found = re.search(r"refs:\s+([\d,]+)", result.stderr)
    if result.returncode != 0 or not found:
        raise RuntimeError(f"callgrind on {' '.join(command)} failed: {result.stderr[-500:]}")
    return int(found.group(1).replace(",", ""))


# libxml2's SAX parse with handlers that do nothing (tests/bench/sax_floor.h):
# the part of the XML formats' compile that is libxml2's own, run in the same
# process as the family's floor and compile
SAX_FLOOR = "libxml2_sax"

# mdlc's compile (Compilation::Run: read, frontends, passes, backend) without
# the printing of its warnings, which the timed benchmarks do not do either;
# xmllint's parse of the file into a DOM, and the DOM's release
MDLC_COMPILE_FUNCTIONS = ["mdlc::Compilation::Run()", "mdlc::FormatDiagnosticText*"]
XMLLINT_PARSE_FUNCTIONS = ["xmlReadFile", "xmlFreeDoc"]
XMLLINT = ["--noout", "--huge", "--noblanks"]
# the most runs of one one-shot row (short processes get more: see the top)
ONE_SHOT_MAX_RUNS = 41


def family_numbers(get, family, floor, small, large):
    """One process's numbers for a family: the floor's and the compile's
    times at the small and the large size, the compile over the floor at
    each size, the growth per element of the compile and of the floor, and
    the one over the other."""
    fs, fl = get(f"{floor}/{family}/{small}"), get(f"{floor}/{family}/{large}")
    cs, cl = get(f"compile/{family}/{small}"), get(f"compile/{family}/{large}")
    growth = ratio(ratio(cl, large), ratio(cs, small))
    floor_growth = ratio(ratio(fl, large), ratio(fs, small))
    return (fs, fl, cs, cl, ratio(cs, fs), ratio(cl, fl), growth, floor_growth,
            ratio(growth, floor_growth))


def median(values):
    values = sorted(values)
    n = len(values)
    return None if n == 0 else (values[n // 2] if n % 2 else (values[n // 2 - 1] + values[n // 2]) / 2)


def fmt_ms(t):
    return "–" if t is None else (f"{t:.3g}" if t < 100 else f"{t:.0f}")


def fmt_ratio(r):
    return "–" if r is None else f"{r:.2f}x"


def ratio(a, b):
    return None if a is None or b is None or b == 0 else a / b


def add_table(add, intro, columns, rows):
    """A paragraph, then a markdown table of `rows` (tuples of cell strings)."""
    add(intro)
    add("")
    add("| " + " | ".join(columns) + " |")
    add("|" + "---|" * len(columns))
    for row in rows:
        add("| " + " | ".join(row) + " |")
    add("")


def verdict(value, goal, at_most=True):
    if value is None:
        return "not measured"
    ok = value <= goal if at_most else value >= goal
    return "met" if ok else "**not met**"


# (label, model) of mdlc_bench_meshes (tests/bench/bench_meshes.cc, issue 57):
# compiles whose time goes to mesh files. The corpus models are read from
# --corpus; the synthetic ones are written by the benchmark itself.
MESH_MODELS = [
    ("synthetic, 100 bodies (MJCF)", "synthetic_n100"),
    ("synthetic, 1000 bodies (MJCF)", "synthetic_n1000"),
    ("Menagerie Allegro hand (MJCF)", "allegro_hand"),
    ("Menagerie Robotiq 2F-85 (MJCF)", "robotiq_2f85"),
    ("Menagerie Shadow hand (MJCF)", "shadow_hand"),
    ("Menagerie TALOS (MJCF)", "talos"),
    ("Menagerie Cassie (MJCF)", "cassie"),
    ("Drake iiwa14 (SDFormat)", "iiwa14"),
    ("Drake Panda arm and hand (URDF)", "panda"),
]


def mesh_numbers(get, model):
    """One process's numbers for a mesh model: the cold compile with child
    readers and in-process, the one over the other, the warm compile with
    child readers, cold over warm, MuJoCo's load, and MuJoCo's over the cold
    compile's."""
    compile_ = f"mesh_compile/{model}"
    cold, cold_here = get(f"{compile_}/cold/process"), get(f"{compile_}/cold/in_process")
    warm, mujoco = get(f"{compile_}/warm/process"), get(f"mujoco_load/{model}")
    return (cold, cold_here, ratio(cold, cold_here), warm, ratio(cold, warm), mujoco,
            ratio(mujoco, cold))


def add_mesh_part(add, exe, corpus, reps, min_time, rounds):
    """The meshes part: a table of mdlc_bench_meshes's models and its goals.
    Wall times, not CPU times: the child readers work in processes of their
    own, which the benchmark process's CPU time leaves out. As for the
    families above, each model runs in a process of its own per round, its
    benchmarks interleaved, and every number is the median over the rounds
    of one process's fastest runs."""
    if not os.path.exists(exe):
        print(f"bench_table: {exe} is not built; skipping the meshes part", file=sys.stderr)
        return
    model_rounds = {model: [] for _, model in MESH_MODELS}
    files, errors = {}, {}
    for _ in range(rounds):
        for _, model in MESH_MODELS:
            runs = benchmark_runs(exe, rf"^(mesh_compile|mujoco_load)/{model}(/|$)", reps,
                                  min_time, [f"--corpus={corpus}"])
            # UseRealTime names its runs NAME/real_time
            model_rounds[model].append({name.removesuffix("/real_time"): t
                                        for name, t in fastest_times(runs, "real_time").items()})
            for b in runs:
                name = b["run_name"].removesuffix("/real_time")
                if b.get("error_occurred"):
                    errors.setdefault(name, " ".join(b.get("error_message", "").split()))
                elif b.get("run_type") == "iteration" and "mesh_files" in b:
                    files[model] = (int(b["mesh_files"]), int(b["cache_entries"]))

    add("Mesh-heavy models (`mdlc_bench_meshes`): `mdlc::Compile` with the mesh cache cold (an "
        "empty folder each run) and warm (filled by one compile before), meshes read by child "
        "processes (the default) and in-process, and MuJoCo 2.2.2's `mj_loadXML` of the same "
        "MJCF file. Wall times: the child readers' work is in other processes. Each model's "
        "benchmarks run interleaved in one process, every number is read from its fastest of "
        f"{reps} runs, and the table shows the median over {rounds} such processes. Mesh files: "
        "the files the model names / the entries a cold compile leaves in the mesh cache (none: "
        "the compile needed no mesh, its bodies' inertia being declared; MuJoCo reads every "
        "mesh all the same). Goals: child processes ≤ 1.2x in-process, cold over warm ≥ 3x, "
        "MuJoCo over mdlc's cold compile ≥ 2x.")
    add("")
    add("| model | mesh files / cache entries | cold, process (ms) | cold, in-process (ms) "
        "| process/in-process | warm, process (ms) | cold/warm | MuJoCo 2.2.2 (ms) "
        "| MuJoCo/cold |")
    add("|---|---|---|---|---|---|---|---|---|")
    summary = {}
    for label, model in MESH_MODELS:
        numbers = [mesh_numbers(times.get, model) for times in model_rounds[model]]
        cold, cold_here, over_here, warm, over_warm, mujoco, over_cold = (
            median([v for v in column if v is not None]) for column in zip(*numbers))
        summary[model] = (over_here, over_warm, over_cold)
        counts = files.get(model)
        add(f"| {label} | {'–' if counts is None else f'{counts[0]} / {counts[1]}'} "
            f"| {fmt_ms(cold)} | {fmt_ms(cold_here)} | {fmt_ratio(over_here)} | {fmt_ms(warm)} "
            f"| {fmt_ratio(over_warm)} | {fmt_ms(mujoco)} | {fmt_ratio(over_cold)} |")
    add("")
    if errors:
        add("Not measured:")
        add("")
        for name, message in sorted(errors.items()):
            add(f"- `{name}`: {message}")
        add("")

    worst_process = max((v[0] for v in summary.values() if v[0] is not None), default=None)
    # a compile that reads no mesh has nothing for the cache to save
    worst_warm = min((v[1] for model, v in summary.items()
                      if v[1] is not None and files.get(model, (0, 0))[1] > 0), default=None)
    worst_mujoco = min((v[2] for v in summary.values() if v[2] is not None), default=None)
    add("| goal | measured | |")
    add("|---|---|---|")
    add(f"| meshes read by child processes ≤ 1.2x in-process, cold cache, every model | worst "
        f"{fmt_ratio(worst_process)} | {verdict(worst_process, 1.2)} |")
    add(f"| warm mesh cache ≥ 3x faster than cold (child processes), every model whose "
        f"compile reads meshes | worst {fmt_ratio(worst_warm)} "
        f"| {verdict(worst_warm, 3, at_most=False)} |")
    add(f"| cold compile ≥ 2x faster than MuJoCo 2.2.2 `mj_loadXML`, every MJCF model it "
        f"loads | worst {fmt_ratio(worst_mujoco)} | {verdict(worst_mujoco, 2, at_most=False)} |")


# (label, model) of mdlc_bench_dynamics (tests/bench/bench_dynamics.cc):
# rigid-body dynamics per call against MuJoCo 2.2.2 on the same MJCF file.
# MuJoCo 2.2.2 reads no element nested deeper than 100, so 96 links is the
# longest chain it loads and chain_n1000 has mdlc's rows alone.
DYNAMICS_MODELS = [
    ("Menagerie KUKA iiwa 14", "iiwa14"),
    ("MuJoCo humanoid", "humanoid"),
    ("chain, 10 links", "chain_n10"),
    ("chain, 96 links", "chain_n96"),
    ("chain, 1000 links", "chain_n1000"),
    ("tree, 1000 links", "tree_n1000"),
]
# (operation, MuJoCo's fair pipeline from qpos, MuJoCo's call alone)
DYNAMICS_OPS = [
    ("inverse_dynamics", "mujoco", "mujoco_rne"),
    ("mass_matrix", "mujoco", "mujoco_crb"),
    ("forward_dynamics", "mujoco", None),
]


def fmt_us(t_ms):
    """A time given in ms, written in microseconds."""
    return "–" if t_ms is None else fmt_ms(t_ms * 1000)


def add_dynamics_part(add, exe, corpus, reps, min_time, rounds):
    """The dynamics part: mdlc's inverse dynamics, mass matrix and forward
    dynamics per call against MuJoCo 2.2.2's on the same files. Each model's
    benchmarks run interleaved in a process of their own per round; every
    number is the median over the rounds of one process's fastest CPU time."""
    if not os.path.exists(exe):
        print(f"bench_table: {exe} is not built; skipping the dynamics part", file=sys.stderr)
        return
    model_rounds = {model: [] for _, model in DYNAMICS_MODELS}
    counters, errors = {}, {}
    for _ in range(rounds):
        for _, model in DYNAMICS_MODELS:
            runs = benchmark_runs(exe, rf"^[a-z_]+/[a-z_]+/{model}$", reps, min_time,
                                  [f"--corpus={corpus}"])
            model_rounds[model].append(fastest_times(runs))
            for b in runs:
                if b.get("error_occurred"):
                    # one line per model and reason: a model MuJoCo cannot load fails every row
                    op, impl, _ = b["run_name"].split("/")
                    message = " ".join(b.get("error_message", "").split())
                    errors.setdefault((model, message), set()).add(f"{op}/{impl}")
                elif b.get("run_type") == "iteration":
                    c = counters.setdefault(model, {})
                    c["nv"] = int(b.get("nv", 0))
                    if "rel_diff" in b:
                        c[b["run_name"]] = b["rel_diff"]

    def med(model, name):
        return median([t[name] for t in model_rounds[model] if name in t])

    add("Rigid-body dynamics per call (`mdlc_bench_dynamics`): mdlc's `InverseDynamics`, "
        "`MassMatrix` and `ForwardDynamics` (each from q, its own kinematics included) "
        "against what MuJoCo 2.2.2 needs for the same answer from qpos: "
        "`mj_kinematics`, `mj_comPos`, `mj_comVel`, `mj_rne` (inverse dynamics); "
        "`mj_kinematics`, `mj_comPos`, `mj_crb`, `mj_fullM` (the dense mass matrix); "
        "`mj_forward` with constraints, contact, passive forces, actuation and sensors "
        "disabled (forward dynamics); and MuJoCo's `mj_rne` and `mj_crb` + `mj_fullM` alone, on "
        "kinematics computed before. Same MJCF file, same random state, gravity on, no "
        "armature, damping or springs on either side. Microseconds, CPU time; each model's "
        f"benchmarks interleaved in one process, fastest of {reps} runs, median over "
        f"{rounds} processes. Agreement: the largest difference between the two answers "
        "over the answer's largest entry. Goal: mdlc ≤ 1.0x MuJoCo's time.")
    add("")
    add("| model (nv) | inverse dynamics, mdlc / MuJoCo (µs) | mdlc/MuJoCo | `mj_rne` alone (µs) "
        "| mass matrix, mdlc / MuJoCo (µs) | mdlc/MuJoCo | `mj_crb`+`mj_fullM` alone (µs) "
        "| forward dynamics, mdlc / MuJoCo (µs) | mdlc/MuJoCo | agreement |")
    add("|---|---|---|---|---|---|---|---|---|---|")
    worst = {}
    for label, model in DYNAMICS_MODELS:
        nv = counters.get(model, {}).get("nv")
        cells = [f"{label} ({'–' if nv is None else nv})"]
        for op, pipeline, alone in DYNAMICS_OPS:
            mdlc_t, mj_t = med(model, f"{op}/mdlc/{model}"), med(model, f"{op}/{pipeline}/{model}")
            r = ratio(mdlc_t, mj_t)
            if r is not None:
                worst[op] = max(worst.get(op, r), r)
            cells += [f"{fmt_us(mdlc_t)} / {fmt_us(mj_t)}", fmt_ratio(r)]
            if alone:
                cells.append(fmt_us(med(model, f"{op}/{alone}/{model}")))
        diffs = [v for k, v in counters.get(model, {}).items() if k != "nv"]
        cells.append("–" if not diffs else f"{max(diffs):.0e}")
        add("| " + " | ".join(cells) + " |")
    add("")

    # linearity: mdlc's time per velocity along the chains
    add("mdlc per velocity along the chains and the tree (µs per dof; goal: the same at "
        "every length for inverse and forward dynamics, which are O(n); a chain's dense mass "
        "matrix has n² nonzero entries, so its time per dof grows as n):")
    add("")
    chains = [m for m in ("chain_n10", "chain_n96", "chain_n1000", "tree_n1000")]
    add("| operation | " + " | ".join(chains) + " | growth per dof, chain 96 → 1000 |")
    add("|---|" + "---|" * (len(chains) + 1))
    growth = {}
    for op, _, _ in DYNAMICS_OPS:
        per_dof = {}
        for model in chains:
            nv = counters.get(model, {}).get("nv")
            t = med(model, f"{op}/mdlc/{model}")
            per_dof[model] = None if not nv or t is None else t * 1000 / nv
        growth[op] = ratio(per_dof["chain_n1000"], per_dof["chain_n96"])
        add(f"| {op.replace('_', ' ')} | "
            + " | ".join("–" if per_dof[m] is None else f"{per_dof[m]:.3g}" for m in chains)
            + f" | {fmt_ratio(growth[op])} |")
    add("")
    if errors:
        add("Not measured:")
        add("")
        for (model, message), rows in sorted(errors.items()):
            add(f"- `{model}`, {', '.join(f'`{r}`' for r in sorted(rows))}: {message}")
        add("")
    add("| goal | measured | |")
    add("|---|---|---|")
    for op, _, _ in DYNAMICS_OPS:
        add(f"| {op.replace('_', ' ')} ≤ 1.0x MuJoCo 2.2.2, every model both load | worst "
            f"{fmt_ratio(worst.get(op))} | {verdict(worst.get(op), 1.0)} |")
    for op in ("inverse_dynamics", "forward_dynamics"):
        add(f"| {op.replace('_', ' ')} linear in bodies: time per dof, chain of 96 to 1000 "
            f"≤ 1.1x | {fmt_ratio(growth[op])} | {verdict(growth[op], 1.1)} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("build", nargs="?", default="build")
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--rounds", type=int, default=5,
                        help="processes per family; the table shows medians over them")
    parser.add_argument("--min_time", default="0.1")
    parser.add_argument("--readme", help="replace the table between the markers in this file")
    parser.add_argument("--no-instructions", dest="instructions", action="store_false",
                        help="skip the instruction counts (callgrind)")
    parser.add_argument("--corpus",
                        default=os.environ.get("MDLC_CORPUS", os.path.join("..", "shared", "corpus")),
                        help="the corpus of real models, for the meshes part "
                             "(default: $MDLC_CORPUS, else ../shared/corpus)")
    parser.add_argument("--only-meshes", action="store_true",
                        help="run the meshes part (mdlc_bench_meshes) alone")
    parser.add_argument("--only-dynamics", action="store_true",
                        help="run the dynamics part (mdlc_bench_dynamics) alone")
    args = parser.parse_args()
    if args.rounds < 1:
        parser.error("--rounds must be at least 1: every number is a median over them")
    if args.only_meshes and args.readme:
        parser.error("--readme replaces the whole table, which --only-meshes does not make")
    if args.only_dynamics and args.readme:
        parser.error("--readme replaces the whole table, which --only-dynamics does not make")

    bench_dir = os.path.join(args.build, "tests", "bench")
    mdlc = os.path.join(args.build, "tools", "mdlc", "mdlc")
    reps, min_time = args.repetitions, args.min_time
    meshes_exe = os.path.join(bench_dir, "mdlc_bench_meshes")
    corpus = os.path.abspath(args.corpus)
    if args.only_meshes:
        lines = []
        add_mesh_part(lines.append, meshes_exe, corpus, reps, min_time, args.rounds)
        print("\n".join(lines))
        return
    dynamics_exe = os.path.join(bench_dir, "mdlc_bench_dynamics")
    if args.only_dynamics:
        lines = []
        add_dynamics_part(lines.append, dynamics_exe, corpus, reps, min_time, args.rounds)
        print("\n".join(lines))
        return

    # paired ratios (see the module's docstring): a process per family and round
    family_rounds = {family: [] for _, family, _, _, _ in FAMILIES}
    reference_rounds = {name: [] for name, _, _, _ in REFERENCES}
    for _ in range(args.rounds):
        for _, family, floor, sizes, exe in FAMILIES:
            stages = [floor, "compile"] + ([SAX_FLOOR] if floor == "libxml2_parse" else [])
            pattern = rf"^({'|'.join(stages)})/{family}/({'|'.join(map(str, sizes))})$"
            family_rounds[family].append(
                run_benchmarks(os.path.join(bench_dir, exe), pattern, reps, min_time))
        for name, exe, reference, compile_name in REFERENCES:
            pattern = f"^({re.escape(reference)}|{re.escape(compile_name)})$"
            times = run_benchmarks(os.path.join(bench_dir, exe), pattern, reps, min_time)
            reference_rounds[name].append(ratio(times.get(reference), times.get(compile_name)))

    def paired(family, value):
        """The median over the rounds of value(one round's times of the family)."""
        return median([v for v in (value(times.get) for times in family_rounds[family])
                       if v is not None])

    lines = []
    add = lines.append
    add("Compile time over the parse floor (the libxml2 or yaml-cpp parse of the same input; "
        "goal ≤ 1.5x), and growth per element from the small to the large size "
        "(goal ≤ 1.1x): the compile's, the floor's own, and the compile's over the floor's "
        "(how much faster than the parse mdlc's own work grows). Each family's floor and "
        "compile, at both sizes, run interleaved in one process, and every number is read "
        f"from one process's fastest CPU times of {reps} runs; the table shows its median over "
        f"{args.rounds} such processes, run one family after another (the floor's runs fall "
        "into two modes, one about twice the other, by the heap its previous run left).")
    add("")
    add("| input | floor, small / large (ms) | compile, small / large (ms) "
        "| compile/floor, small | compile/floor, large | growth per element "
        "| floor's growth | growth over the floor's |")
    add("|---|---|---|---|---|---|---|---|")
    summary = {}
    for label, family, floor, sizes, _ in FAMILIES:
        small, large = sizes[0], sizes[-1]
        numbers = [family_numbers(times.get, family, floor, small, large)
                   for times in family_rounds[family]]
        fs, fl, cs, cl, *row = (median([v for v in column if v is not None])
                                for column in zip(*numbers))
        summary[family] = row
        add(f"| {label}, N = {small} / {large} | {fmt_ms(fs)} / {fmt_ms(fl)} "
            f"| {fmt_ms(cs)} / {fmt_ms(cl)} | " + " | ".join(fmt_ratio(v) for v in row) + " |")
    add("")

    # the XML formats against libxml2's SAX events alone: how much of each
    # compile is libxml2's own work, and how much mdlc adds to it
    add("The same compiles against libxml2's SAX parse alone, with handlers that do nothing "
        "(`libxml2_sax`, run in the same processes): the least a reader built on libxml2's "
        "events, as mdlc's is, pays for the file.")
    add("")
    add("| input | SAX events alone, small / large (ms) | compile/SAX, small "
        "| compile/SAX, large | SAX's growth per element |")
    add("|---|---|---|---|---|")
    for label, family, floor, sizes, _ in FAMILIES:
        if floor != "libxml2_parse":
            continue
        small, large = sizes[0], sizes[-1]
        ss = paired(family, lambda get: get(f"{SAX_FLOOR}/{family}/{small}"))
        sl = paired(family, lambda get: get(f"{SAX_FLOOR}/{family}/{large}"))
        over_small = paired(family, lambda get: ratio(get(f"compile/{family}/{small}"),
                                                      get(f"{SAX_FLOOR}/{family}/{small}")))
        over_large = paired(family, lambda get: ratio(get(f"compile/{family}/{large}"),
                                                      get(f"{SAX_FLOOR}/{family}/{large}")))
        sax_growth = paired(family, lambda get: ratio(
            ratio(get(f"{SAX_FLOOR}/{family}/{large}"), large),
            ratio(get(f"{SAX_FLOOR}/{family}/{small}"), small)))
        add(f"| {label}, N = {small} / {large} | {fmt_ms(ss)} / {fmt_ms(sl)} "
            f"| {fmt_ratio(over_small)} | {fmt_ratio(over_large)} | {fmt_ratio(sax_growth)} |")
    add("")

    # worlds: the per-model cost at each size
    add("| world of N one-link models | N = 1000 | N = 10000 | N = 100000 |")
    add("|---|---|---|---|")
    sizes = (1000, 10000, 100000)
    add("| compile (ms) | " + " | ".join(
        fmt_ms(paired("world", lambda get, n=n: get(f"compile/world/{n}"))) for n in sizes) + " |")
    add("| compile/floor | " + " | ".join(
        fmt_ratio(paired("world", lambda get, n=n: ratio(get(f"compile/world/{n}"),
                                                         get(f"libxml2_parse/world/{n}"))))
        for n in sizes) + " |")
    def per_thousand_models(stage):
        return [paired("world", lambda get, n=n: ratio(get(f"{stage}/world/{n}"), n / 1000.0))
                for n in sizes]
    for label, stage in [("compile", "compile"), ("floor", "libxml2_parse"),
                         ("SAX events alone", SAX_FLOOR)]:
        add(f"| {label} per 1000 models (ms) | "
            + " | ".join(fmt_ms(p) for p in per_thousand_models(stage)) + " |")
    world_growth = summary["world"][2]  # the family's growth per model, 1k to 100k
    add("")

    # whole processes: peak memory against the DOM's (xmllint's parse of the
    # same file), and one-shot CPU time, first touch of every page included
    work = tempfile.mkdtemp(prefix="mdlc_bench_table_")
    memory_rows = []
    process_rows = []
    instruction_rows = []
    try:
        for exe in ("mdlc_bench", "mdlc_bench_sdf"):
            subprocess.run([os.path.join(bench_dir, exe), f"--write_models={work}"], check=True,
                           capture_output=True)
        xmllint = shutil.which("xmllint")
        for label, name in [("URDF chain, N = 10000", "chain_n10000.urdf"),
                            ("MJCF tree, N = 10000", "tree_n10000.mjcf.xml"),
                            ("SDFormat chain, N = 10000", "sdf_chain_n10000.sdf"),
                            ("SDFormat nested models, N = 1000", "nested_models_n1000.sdf"),
                            ("SDFormat nested models, N = 10000", "nested_models_n10000.sdf"),
                            ("SDFormat world, N = 1000", "world_n1000.sdf"),
                            ("SDFormat world, N = 100000", "world_n100000.sdf")]:
            path = os.path.join(work, name)
            if not os.path.exists(path) or not xmllint:
                continue
            compile_runs, parse_runs = [], []

            def run_both():  # alternating, so load changes hit both alike
                compile_runs.append(measure_process([mdlc, "compile", path] + MDLC_FLAGS))
                parse_runs.append(measure_process([xmllint] + XMLLINT + [path]))

            run_both()  # the first pair's time sets how many runs fill about a second
            first_ms = max(compile_runs[0][0] + parse_runs[0][0], 1.0)
            for _ in range(max(reps, min(ONE_SHOT_MAX_RUNS, int(1000.0 / first_ms))) - 1):
                run_both()
            compile_kb, dom_kb = compile_runs[0][1], parse_runs[0][1]
            if not name.startswith("world_n1000."):
                memory_rows.append((label, dom_kb, compile_kb))
            process_rows.append((label, median([r[0] for r in parse_runs]),
                                 median([r[0] for r in compile_runs])))
        if args.instructions and shutil.which("valgrind") and xmllint:
            for label, small, large in [("URDF chain", "chain_n1000.urdf", "chain_n10000.urdf"),
                                        ("MJCF tree", "tree_n1000.mjcf.xml",
                                         "tree_n10000.mjcf.xml"),
                                        ("SDFormat chain", "sdf_chain_n1000.sdf",
                                         "sdf_chain_n10000.sdf"),
                                        ("SDFormat nested models", "nested_models_n1000.sdf",
                                         "nested_models_n10000.sdf"),
                                        ("SDFormat world", "world_n1000.sdf",
                                         "world_n10000.sdf")]:
                counts = []
                for name in (small, large):
                    path = os.path.join(work, name)
                    counts.append((
                        count_instructions([xmllint] + XMLLINT + [path], XMLLINT_PARSE_FUNCTIONS),
                        count_instructions([mdlc, "compile", path] + MDLC_FLAGS,
                                           MDLC_COMPILE_FUNCTIONS)))
                instruction_rows.append((label, counts))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    memory = {label: compile_kb / dom_kb for label, dom_kb, compile_kb in memory_rows}
    add_table(add, "Peak memory (resident set) of `mdlc compile --emit=none` against "
              "`xmllint --noout` holding the file's DOM (goal ≤ 2x):",
              ["input", "DOM (MB)", "mdlc compile (MB)", "ratio"],
              [(label, f"{dom_kb / 1024:.0f}", f"{compile_kb / 1024:.0f}",
                fmt_ratio(compile_kb / dom_kb)) for label, dom_kb, compile_kb in memory_rows])
    one_shot = {label: (parse_ms, compile_ms) for label, parse_ms, compile_ms in process_rows}
    add_table(add, "One-shot processes: CPU time (user + system, median of "
              f"{reps} runs, or as many as take about a second, up to {ONE_SHOT_MAX_RUNS}) "
              "of `mdlc compile --emit=none` against `xmllint --noout` parsing "
              "the same file, each a fresh process that touches all its memory for the first "
              "time, as a command-line compile does (goal ≤ 1.5x):",
              ["input", "xmllint (ms)", "mdlc compile (ms)", "ratio"],
              [(label, fmt_ms(parse_ms), fmt_ms(compile_ms),
                fmt_ratio(ratio(compile_ms, parse_ms)))
               for label, parse_ms, compile_ms in process_rows])
    worst_instructions = worst_instruction_growth = None
    if instruction_rows:
        rows = []
        for label, ((floor_s, compile_s), (floor_l, compile_l)) in instruction_rows:
            growth = ratio(ratio(compile_l, 10), compile_s)
            relative = ratio(growth, ratio(ratio(floor_l, 10), floor_s))
            worst_instructions = max(worst_instructions or 0, compile_s / floor_s,
                                     compile_l / floor_l)
            worst_instruction_growth = max(worst_instruction_growth or 0, growth)
            rows.append((f"{label}, N = 1000 / 10000", f"{floor_s / 1e6:.0f} / {floor_l / 1e6:.0f}",
                         f"{compile_s / 1e6:.0f} / {compile_l / 1e6:.0f}",
                         fmt_ratio(compile_s / floor_s), fmt_ratio(compile_l / floor_l),
                         fmt_ratio(growth), fmt_ratio(relative)))
        add_table(add, "The same work counted in instructions (valgrind's callgrind, one run "
                  "each; the same on every run): mdlc's compile (`Compilation::Run`, without "
                  "printing its warnings) against xmllint's parse of the file into a DOM and "
                  "its release (`xmlReadFile`, `xmlFreeDoc`):",
                  ["input", "parse (M instructions)", "compile (M instructions)",
                   "compile/parse, small", "compile/parse, large", "growth per element",
                   "growth over the parse's"], rows)

    small_world, large_world = (one_shot.get("SDFormat world, N = 1000"),
                                one_shot.get("SDFormat world, N = 100000"))
    one_shot_world_growth = one_shot_world_floor_growth = None
    if small_world and large_world:
        one_shot_world_growth = ratio(ratio(large_world[1], 100), small_world[1])
        one_shot_world_floor_growth = ratio(ratio(large_world[0], 100), small_world[0])
    worst_one_shot = max((ratio(c, p) for label, (p, c) in one_shot.items()
                          if label != "SDFormat world, N = 1000" and ratio(c, p) is not None),
                         default=None)

    # nesting ten times deeper: ten times the elements
    nest_growth, nest_floor_growth, nest_relative = summary["nested_models"][2:5]
    nest = None if nest_growth is None else 10 * nest_growth
    nest_floor = None if nest_floor_growth is None else 10 * nest_floor_growth
    reference = {name: median([r for r in rounds if r is not None])
                 for name, rounds in reference_rounds.items()}
    sdformat_chain, sdformat_world = reference["sdformat_chain"], reference["sdformat_world"]
    mujoco = reference["mujoco"]

    add("| goal | measured | |")
    add("|---|---|---|")
    worst_large = max((v[1] for v in summary.values() if v[1] is not None), default=None)
    add(f"| compile ≤ 1.5x the parse floor, every input at the large size | worst "
        f"{fmt_ratio(worst_large)} | {verdict(worst_large, 1.5)} |")
    worst_small = max((v[0] for v in summary.values() if v[0] is not None), default=None)
    add(f"| compile ≤ 1.5x the parse floor, every input at the small size | worst "
        f"{fmt_ratio(worst_small)} | {verdict(worst_small, 1.5)} |")
    add(f"| compile ≤ 1.5x the parse floor, counted in instructions, at both sizes | worst "
        f"{fmt_ratio(worst_instructions)} | {verdict(worst_instructions, 1.5)} |")
    worst_growth = max((v[2] for v in summary.values() if v[2] is not None), default=None)
    worst_floor_growth = max((v[3] for v in summary.values() if v[3] is not None), default=None)
    worst_relative = max((v[4] for v in summary.values() if v[4] is not None), default=None)
    # the compile includes the parse: an input whose parse alone grows more
    # than 1.1x per element on this machine cannot meet the goal as stated
    failing = [v for v in summary.values() if v[2] is not None and v[2] > 1.1]
    unattainable = bool(failing) and all(v[3] is not None and v[3] > 1.1 for v in failing)
    growth_verdict = ("not attainable as stated: in each input over it, the parse floor alone "
                      "grows more than 1.1x" if unattainable else verdict(worst_growth, 1.1))
    add(f"| growth per element ≤ 1.1x, small to large | worst {fmt_ratio(worst_growth)} "
        f"(the parse floor alone: worst {fmt_ratio(worst_floor_growth)}) | {growth_verdict} |")
    add(f"| growth per element over the floor's ≤ 1.1x | worst {fmt_ratio(worst_relative)} "
        f"| {verdict(worst_relative, 1.1)} |")
    add(f"| growth per element ≤ 1.1x, counted in instructions | worst "
        f"{fmt_ratio(worst_instruction_growth)} | {verdict(worst_instruction_growth, 1.1)} |")
    add(f"| compile ≤ 1.5x the parse floor, one-shot processes at the large size | worst "
        f"{fmt_ratio(worst_one_shot)} | {verdict(worst_one_shot, 1.5)} |")
    add(f"| world: per-model time 1k to 100k ≤ 1.1x | {fmt_ratio(world_growth)} "
        f"| {verdict(world_growth, 1.1)} |")
    add(f"| world, one-shot processes: per-model time 1k to 100k ≤ 1.1x "
        f"| {fmt_ratio(one_shot_world_growth)} (xmllint alone: "
        f"{fmt_ratio(one_shot_world_floor_growth)}) | {verdict(one_shot_world_growth, 1.1)} |")
    add(f"| nesting 10,000 deep vs 1,000 deep (linear: about 10x) | {fmt_ratio(nest)} "
        f"(the parse floor alone: {fmt_ratio(nest_floor)}) | {verdict(nest, 12)} |")
    add(f"| nesting: growth over the parse floor's ≤ 1.1x | "
        f"{fmt_ratio(nest_relative)} | {verdict(nest_relative, 1.1)} |")
    worst_memory = max(memory.values(), default=None)
    add(f"| peak memory ≤ 2x the DOM's | worst {fmt_ratio(worst_memory)} "
        f"| {verdict(worst_memory, 2)} |")
    add(f"| MJCF 1k-body tree ≥ 10x faster than MuJoCo 2.2.2 `mj_loadXML` | {fmt_ratio(mujoco)} "
        f"| {verdict(mujoco, 10, at_most=False)} |")
    add(f"| faster than libsdformat 12 (SDFormat chain / world, N = 1000) "
        f"| {fmt_ratio(sdformat_chain)} / {fmt_ratio(sdformat_world)} | |")
    if os.path.exists(meshes_exe):
        add("")
        add_mesh_part(add, meshes_exe, corpus, reps, min_time, args.rounds)

    table = "\n".join(lines)
    print(table)
    if args.readme:
        with open(args.readme, encoding="utf-8") as f:
            text = f.read()
        pattern = re.compile(re.escape(BEGIN) + ".*?" + re.escape(END), re.S)
        if not pattern.search(text):
            sys.exit(f"bench_table: no {BEGIN} ... {END} markers in {args.readme}")
        text = pattern.sub(lambda _: f"{BEGIN}\n{table}\n{END}", text)
        with open(args.readme, "w", encoding="utf-8") as f:
            f.write(text)


if __name__ == "__main__":
    main()
