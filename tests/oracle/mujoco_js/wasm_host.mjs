// wasm_host.mjs - test-only: what mujoco_dump.mjs and mujoco_dynamics.mjs
// share in running MuJoCo 3.3.8's WebAssembly module (npm mujoco-js 0.0.7):
// starting it, mirroring files into its file system, loading one file per
// request with MuJoCo's messages and exceptions turned into the answer,
// answering FILE arguments or --serve requests one JSON line each, and the
// names and seeded random numbers both read and draw.
//
// Files: the module has its own in-memory file system, so the folder holding
// FILE (and, when any XML below it reaches up with "../" in a file, meshdir,
// texturedir or assetdir attribute, as many levels above as that needs) is
// copied into it at the same absolute path before loading; includes, meshes
// and textures then resolve as they do for MuJoCo on disk.
import fs from 'node:fs';
import path from 'node:path';
import loadMujoco from 'mujoco-js';

// The running module instance (a live binding: dumpFile replaces it after a
// failed load).
export let mj = null;

// Messages the module prints (e.g. "Loading error: ...") are collected per
// file instead of going to the terminal.
let printed = [];

// Files (and mirrored folders) already copied into the current instance.
const mirrored = new Set();

// Starts a fresh module instance, with an empty file system.
export async function startModule() {
  mj = await loadMujoco({
    print: (s) => printed.push(String(s)),
    printErr: (s) => printed.push(String(s)),
  });
  mirrored.clear();
  return mj;
}

// ------------------------------------------------------------ file mirroring
function mkdirp(dir) {
  let cur = '';
  for (const p of dir.split('/').filter(Boolean)) {
    cur += '/' + p;
    try { mj.FS.mkdir(cur); } catch (e) { /* exists */ }
  }
}

function listTree(dir, out) {
  let entries = [];
  try { entries = fs.readdirSync(dir, { withFileTypes: true }); } catch (e) { return; }
  for (const e of entries) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) listTree(p, out);
    else if (e.isFile() || e.isSymbolicLink()) out.push(p);
  }
}

// How many levels above its folder an XML file reaches with "../".
function upLevels(xmlFile) {
  let text = '';
  try { text = fs.readFileSync(xmlFile, 'utf8'); } catch (e) { return 0; }
  let most = 0;
  const re = /\b(?:file|meshdir|texturedir|assetdir)\s*=\s*"((?:\.\.\/|\.\/)*)/g;
  for (let m; (m = re.exec(text));) most = Math.max(most, (m[1].match(/\.\.\//g) || []).length);
  return most;
}

// The folder to mirror for `file`: its own, and the levels above it that
// "../" references below it reach.
function rootFor(file) {
  let root = path.dirname(file);
  for (let guard = 0; guard < 8; ++guard) {
    const tree = [];
    listTree(root, tree);
    let need = 0;
    for (const f of tree) {
      if (!f.endsWith('.xml')) continue;
      const depth = path.relative(root, path.dirname(f)).split(path.sep).filter(Boolean).length;
      need = Math.max(need, upLevels(f) - depth);
    }
    if (need <= 0 || path.dirname(root) === root) break;
    for (let k = 0; k < need; ++k) root = path.dirname(root);
  }
  return root;
}

function mirror(root) {
  if (mirrored.has(root)) return;
  const tree = [];
  listTree(root, tree);
  for (const f of tree) {
    if (mirrored.has(f)) continue;
    mkdirp(path.dirname(f));
    try { mj.FS.writeFile(f, fs.readFileSync(f)); } catch (e) { /* unreadable: MuJoCo reports it */ }
    mirrored.add(f);
  }
  mirrored.add(root);
}

// ------------------------------------------------------------------- helpers
function heapU8() {
  const b = new mj.DoubleBuffer(1);
  const view = new Uint8Array(b.GetView().buffer);
  b.delete();
  return view;
}

// MuJoCo's exceptions (mjXError, mjCError) hold the message as their first
// member, a NUL-terminated char array.
function exceptionText(e) {
  if (e && typeof e.excPtr === 'number') {
    const heap = heapU8();
    const bytes = [];
    for (let i = e.excPtr; i < heap.length && heap[i] && bytes.length < 4000; ++i) bytes.push(heap[i]);
    return `${e.name || 'error'}: ${Buffer.from(bytes).toString('utf8').trim()}`;
  }
  return String(e && e.message ? e.message : e);
}

// The name at adrArray[id] in the model's names buffer ("" when unnamed).
export function nameOf(m, adrArray, id) {
  const adr = adrArray[id];
  const names = m.names;
  let s = '';
  for (let i = adr; i < names.length && names[i] !== 0; ++i) s += String.fromCharCode(names[i] & 0xff);
  return Buffer.from(s, 'latin1').toString('utf8');
}

// The seeded PRNG the scripts draw configurations and states from: uniform
// in [0, 1), the same sequence for the same seed on every run.
export function mulberry32(a) {
  return () => {
    a |= 0; a = (a + 0x6D2B79F5) | 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// ------------------------------------------------------------------ requests
// A module that failed a file is not used again: MuJoCo's compiler leaves
// its error handler installed when a load ends in an exception, so the next
// model's runtime error (mju_error) would jump into a finished compile and
// surface as a bare "Error". A fresh instance (about 0.1 s) keeps every
// file's dump what a process of its own would print.
let moduleFailed = false;

// One file's line of output: dumpModel(file, m) of the model MuJoCo loads
// from `file`, or {file, ok: false, error}. Options: root, the folder to
// mirror instead of the file's own (see above); messages, whether an ok
// line also holds what the module printed while loading, as "messages".
export async function dumpFile(file, dumpModel, { root = null, messages = false } = {}) {
  printed = [];
  if (!fs.existsSync(file)) return { file, ok: false, error: `no such file: ${file}` };
  if (moduleFailed) {
    await startModule();
    moduleFailed = false;
  }
  mirror(root || rootFor(file));
  let line;
  let m = null;
  try {
    m = mj.MjModel.loadFromXML(file);
    if (!m) line = { file, ok: false, error: printed.join('\n').trim() || 'load failed' };
    else line = dumpModel(file, m);
  } catch (e) {
    line = { file, ok: false, error: exceptionText(e) };
  } finally {
    if (m) m.delete();
  }
  if (messages) {
    const warnings = printed.filter((s) => s.trim());
    if (line.ok && warnings.length) line.messages = warnings;
  }
  if (!line.ok) moduleFailed = true;
  return line;
}

// Writes answer(file)'s line for each of `files` in order or, with `serve`,
// for each path read from stdin, one per line, as it arrives, until stdin
// closes: a test dumping many files starts Node.js and MuJoCo once.
export async function answerAll(files, serve, answer) {
  if (serve) {
    const readline = await import('node:readline');
    const lines = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
    for await (const request of lines) {
      if (!request) continue;
      process.stdout.write(JSON.stringify(await answer(path.resolve(request))) + '\n');
    }
  } else {
    for (const file of files) process.stdout.write(JSON.stringify(await answer(file)) + '\n');
  }
}
