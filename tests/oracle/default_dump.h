// default_dump.h - mdlc's dump of a file at its default configuration, run
// once for the two checks of an oracle test that ask for it.
//
// The urdfdom and libsdformat oracle tests check each file twice: a static
// check at the default configuration, and a kinematic one whose
// configuration 0 is that same configuration, the same mdlc command line.
// Run as one process over many files (the converted models, tests/convert),
// each file was compiled at its default configuration twice. The first of
// the two checks now keeps mdlc's dump and the second takes it: mdlc's output
// is a function of its command line (the Determinism tests hold it to that),
// so the second check reads what a run of its own would print. A run that
// fails, or that a table lists, is not kept: each check runs it and reports
// it in its own words.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "oracle_util.h"

namespace mdlc::oracle {

/// RunMdlc at the default configuration (no --q), the second time for the
/// same command line from what the first run printed.
inline bool RunMdlcAtDefault(const std::string& file, const std::string& package_path,
                             const std::optional<ListedRejection>& listed, Report* rep, Dump* d,
                             const std::vector<std::string>& extra = {}) {
  static std::map<std::string, Dump> kept;  // by command line, until its second use
  const std::string cmdline = Quote(PlantJsonCommand(file, package_path, {}, extra));
  if (auto it = kept.find(cmdline); it != kept.end()) {
    d->root = std::move(it->second.root);
    d->cmdline = cmdline;
    kept.erase(it);
    IndexDump(d);
    return true;
  }
  const size_t before = rep->size();
  if (!RunMdlc(file, package_path, {}, listed, rep, d, extra)) return false;
  if (rep->size() == before) {
    Dump& copy = kept[cmdline];
    copy.root = d->root;
    copy.cmdline = d->cmdline;
  }
  return true;
}

}  // namespace mdlc::oracle
