// mjcf_document.cc - <include file> (MJCF-001): every include reachable from
// the main file is loaded up front, and MjcfDocument::Children splices an
// included file's root children where its <include> stands.
//
// Paths follow MuJoCo 3: an absolute path as is; else relative to the MAIN
// file's directory, and failing that (MuJoCo's newer rule for nested
// includes) relative to the directory of the file holding the <include>.
// A file included twice is an error in MuJoCo ("already included"); a file
// that includes itself, directly or not, is reported as a cycle with the
// whole include chain as notes. Both walks use explicit stacks.
#include <absl/container/inlined_vector.h>
#include <fmt/format.h>

#include <filesystem>
#include <unordered_set>

#include "frontend/mjcf/mjcf_reader_detail.h"
#include "ir/load_report.h"

namespace mdlc::frontend::mjcf {

std::string CanonicalPath(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : p.string();
}

namespace {

namespace fs = std::filesystem;

/// One file on the include chain: its canonical path and the <include>
/// that brought it in (invalid for the main file).
struct ChainLink {
  std::string canonical;
  Loc include_loc;
};

}  // namespace

std::vector<xml::XmlElement> MjcfDocument::Children(const xml::XmlElement& e) const {
  std::vector<xml::XmlElement> out;
  out.reserve(8);  // a body's inertial, joints, geoms and child bodies: one allocation
  // a stack of sibling cursors: entering an include pushes the included
  // root's first child; leaving it resumes after the include
  absl::InlinedVector<xml::XmlElement, 4> cursors{e.FirstChild()};
  while (!cursors.empty()) {
    xml::XmlElement& cursor = cursors.back();
    if (!cursor) {
      cursors.pop_back();
      continue;
    }
    xml::XmlElement current = cursor;
    cursor = cursor.NextSibling();
    if (current.Name() == "include") {
      auto it = includes.find(current.raw());
      if (it != includes.end()) cursors.push_back(it->second.FirstChild());
      continue;
    }
    out.push_back(current);
  }
  return out;
}

bool LoadIncludes(const xml::XmlElement& root, const std::string& main_dir, FrontendContext& ctx,
                  MjcfDocument& document) {
  // the element counts say whether there is any <include> to find, so a
  // file without one is not walked (at 10,000 bodies the walk cost as much
  // as lowering a body's joints: the tree is out of the cache by then)
  if (document.documents.front()->CountOf("include") == 0) return true;
  const size_t errors_before = ctx.diags.error_count();
  // each file's elements share one context: where the file is and the
  // files from the main file to it
  struct FileContext {
    std::string dir;
    std::vector<ChainLink> chain;
  };
  std::vector<FileContext> files;
  files.push_back({main_dir, {{CanonicalPath(ctx.sources.Path(root.GetLoc().file)), {}}}});
  std::unordered_set<std::string> included;
  // a pre-order walk in document order: an element's next sibling is
  // stacked before its children, so it comes after them
  struct Work {
    xml::XmlElement element;
    size_t file;  // index into `files`
  };
  std::vector<Work> stack{{root, 0}};

  while (!stack.empty()) {
    const Work work = stack.back();
    stack.pop_back();
    const xml::XmlElement e = work.element;
    if (!e) continue;
    stack.push_back({e.NextSibling(), work.file});
    if (e.Name() != "include") {
      stack.push_back({e.FirstChild(), work.file});
      continue;
    }
    const std::string& work_dir = files[work.file].dir;

    if (e.FirstChild()) {
      ctx.diags.Report(DiagKind::BadValue, e.GetLoc(), "an <include> element cannot have children");
    }
    const xml::XmlAttribute file = e.Attribute("file");
    if (!file.present()) {
      ctx.diags.Report(DiagKind::MissingAttribute, e.GetLoc(),
                       "<include> is missing required attribute 'file'");
      continue;
    }
    const std::string name(file.value);
    std::string path;
    if (fs::path(name).is_absolute()) {
      path = name;
    } else {
      std::error_code ec;
      path = (fs::path(main_dir) / name).string();
      if (!fs::exists(path, ec) && work_dir != main_dir) {
        std::string nested = (fs::path(work_dir) / name).string();
        if (fs::exists(nested, ec)) path = nested;
      }
    }
    const std::string canonical = CanonicalPath(path);

    // a cycle: the file is already on the chain that leads here
    const std::vector<ChainLink>& work_chain = files[work.file].chain;
    bool cycle = false;
    for (const ChainLink& link : work_chain) cycle |= (link.canonical == canonical);
    if (cycle) {
      auto diag = ctx.diags.Report(
          DiagKind::IncludeCycle, file.loc,
          fmt::format("include cycle: '{}' includes itself through this include", name));
      for (const ChainLink& link : work_chain) {
        if (link.include_loc.valid()) {
          diag.Note(link.include_loc, fmt::format("'{}' is included here", link.canonical));
        }
      }
      continue;
    }
    if (!included.insert(canonical).second) {
      ctx.diags.Report(DiagKind::DuplicateInclude, file.loc,
                       fmt::format("file '{}' is already included; MuJoCo includes each file "
                                   "at most once",
                                   name));
      continue;
    }

    LoadError error;
    auto id = ctx.sources.LoadFile(path, file.loc, &error);
    if (!id) {
      ReportLoadError(ctx.diags, file.loc, error,
                      fmt::format("cannot read the included file '{}'", name));
      continue;
    }
    std::shared_ptr<const xml::XmlDocument> doc = ParseXml(*id, ctx);
    if (!doc) continue;  // reported by the parser, inside the included file
    document.documents.push_back(doc);
    const xml::XmlElement included_root = doc->Root();
    if (!included_root.FirstChild()) {
      ctx.diags.Report(DiagKind::EmptyFile, file.loc,
                       fmt::format("the included file '{}' has no elements under its root", name));
    }
    document.includes.emplace(e.raw(), included_root);

    std::vector<ChainLink> chain = work_chain;  // copied before `files` grows
    chain.push_back({canonical, file.loc});
    const std::string dir = fs::path(path).parent_path().string();
    files.push_back({dir.empty() ? std::string(".") : dir, std::move(chain)});
    stack.push_back({included_root.FirstChild(), files.size() - 1});
  }
  return ctx.diags.error_count() == errors_before;
}

}  // namespace mdlc::frontend::mjcf
