// sax_floor.h - a second, lower floor for the load-time benchmarks:
// libxml2's SAX parse of a document with handlers that do nothing.
//
// mdlc never takes libxml2's DOM: its tree builder (frontend/xml/) listens
// to libxml2's SAX events. Reading the text through the same callbacks, with
// the same options and the same handler slots set, but building nothing,
// times what libxml2 itself costs mdlc: the least any reader built on
// libxml2 pays for the document. The DOM parse (`libxml2_parse`) stays the
// floor the goals are judged against; this one says how much of a compile is
// libxml2's and how much is mdlc's own.
#pragma once

#include <string_view>

#include <benchmark/benchmark.h>

namespace mdlc::bench {

/// Parses `text` as mdlc's XmlDocument does, every SAX event ignored.
/// False when libxml2 found the text not well formed.
bool ParseWithEmptySaxHandlers(std::string_view text);

/// The `libxml2_sax` stage: ParseWithEmptySaxHandlers(text) once per
/// iteration (the caller reports complexity and bytes).
void TimeEmptySaxParse(benchmark::State& state, std::string_view text);

}  // namespace mdlc::bench
