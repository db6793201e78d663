// dart_model_loader.cc - see dart_model_loader.h.
#include "dart_model_loader.h"

#include <dart/common/LocalResourceRetriever.hpp>
#include <dart/common/Resource.hpp>
#include <dart/common/ResourceRetriever.hpp>
#include <dart/common/Uri.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/Inertia.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/utils/sdf/SdfParser.hpp>
#include <dart/utils/urdf/DartLoader.hpp>
#include <tinyxml2.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <regex>
#include <set>
#include <sstream>

namespace mdlc::oracle {
namespace {

// A file held in memory, for DART's resource interface.
class TextResource : public dart::common::Resource {
 public:
  explicit TextResource(std::string text) : text_(std::move(text)) {}
  std::size_t getSize() override { return text_.size(); }
  std::size_t tell() override { return pos_; }
  bool seek(ptrdiff_t offset, SeekType origin) override {
    const ptrdiff_t base = origin == SEEKTYPE_CUR ? static_cast<ptrdiff_t>(pos_)
                           : origin == SEEKTYPE_END ? static_cast<ptrdiff_t>(text_.size())
                                                    : 0;
    const ptrdiff_t to = base + offset;
    if (to < 0 || to > static_cast<ptrdiff_t>(text_.size())) return false;
    pos_ = static_cast<std::size_t>(to);
    return true;
  }
  std::size_t read(void* buffer, std::size_t size, std::size_t count) override {
    if (size == 0) return 0;
    const std::size_t n = std::min(count, (text_.size() - pos_) / size);
    std::memcpy(buffer, text_.data() + pos_, n * size);
    pos_ += n * size;
    return n;
  }

 private:
  std::string text_;
  std::size_t pos_ = 0;
};

// Serves the adapted model text under the file's URI and nothing else: with
// the geometry gone, DART has no other file to read.
class TextRetriever : public dart::common::ResourceRetriever {
 public:
  TextRetriever(std::string uri, std::string text) : uri_(std::move(uri)), text_(std::move(text)) {}
  bool exists(const dart::common::Uri& uri) override { return uri.toString() == uri_; }
  dart::common::ResourcePtr retrieve(const dart::common::Uri& uri) override {
    if (!exists(uri)) return nullptr;
    return std::make_shared<TextResource>(text_);
  }

 private:
  std::string uri_, text_;
};

// Collects what DART prints (its warnings go to std::cerr, its messages to
// std::cout) while alive, so that a failure can show it and a pass stays quiet.
class CaptureOutput {
 public:
  CaptureOutput() : out_(std::cout.rdbuf(buffer_.rdbuf())), err_(std::cerr.rdbuf(buffer_.rdbuf())) {}
  ~CaptureOutput() {
    std::cout.rdbuf(out_);
    std::cerr.rdbuf(err_);
  }
  std::string text() const { return buffer_.str(); }

 private:
  std::stringstream buffer_;
  std::streambuf* out_;
  std::streambuf* err_;
};

bool IsTagEnd(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '>' || c == '/'; }

// Position of the next "<name" start tag at or after `from`, or npos.
size_t FindStartTag(const std::string& text, const std::string& name, size_t from) {
  const std::string open = "<" + name;
  for (size_t at = text.find(open, from); at != std::string::npos; at = text.find(open, at + 1)) {
    const size_t after = at + open.size();
    if (after < text.size() && IsTagEnd(text[after])) return at;
  }
  return std::string::npos;
}

// Depth of <model> elements inside one another (2 or more: nested models).
int MaxModelDepth(const std::string& text) {
  int depth = 0, max_depth = 0;
  for (size_t at = text.find("<model"); at != std::string::npos;) {
    const size_t close = text.find("</model>", at);
    const size_t open = FindStartTag(text, "model", at);
    if (open != std::string::npos && (close == std::string::npos || open < close)) {
      const size_t gt = text.find('>', open);
      if (gt != std::string::npos && text[gt - 1] != '/') max_depth = std::max(max_depth, ++depth);
      at = gt == std::string::npos ? gt : gt + 1;
    } else if (close != std::string::npos) {
      --depth;
      at = close + 8;
    } else {
      break;
    }
  }
  return max_depth;
}

// The SDFormat version as major * 100 + minor (1.6 -> 106), -1 if absent.
int SdfVersion(const std::string& text, size_t* value_begin, size_t* value_end) {
  static const std::regex kVersion(R"(<sdf[^>]*version\s*=\s*["']([0-9]+)\.([0-9]+)["'])");
  std::smatch m;
  if (!std::regex_search(text, m, kVersion)) return -1;
  *value_begin = static_cast<size_t>(m.position(1));
  *value_end = static_cast<size_t>(m.position(2) + m.length(2));
  return std::stoi(m.str(1)) * 100 + std::stoi(m.str(2));
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

void LoadUrdf(const std::string& path, std::string text, DartModel* model) {
  CaptureOutput capture;  // also DART's complaint about the zero inertia below
  dart::utils::DartLoader::Options options;
  // URDF's default for a link without <inertial> (DART's own is mass 1)
  options.mDefaultInertia =
      dart::dynamics::Inertia(0.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
  dart::utils::DartLoader loader(options);
  dart::dynamics::SkeletonPtr skeleton =
      loader.parseSkeletonString(text, dart::common::Uri::createFromPath(path));
  model->log = capture.text();
  if (!skeleton) {
    model->skip_reason = "DartLoader cannot read it";
    return;
  }
  model->skeletons.push_back(skeleton);
}

std::string Trimmed(const char* text) {
  std::string s = text ? text : "";
  const size_t begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r\n") - begin + 1);
}

void ForEachModel(tinyxml2::XMLElement* element,
                  const std::function<void(tinyxml2::XMLElement*)>& visit) {
  for (auto* e = element->FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (std::strcmp(e->Name(), "model") == 0) visit(e);
    ForEachModel(e, visit);
  }
}

// DART 6.12's SdfParser aborts (assert) on a joint whose parent or child it
// cannot find by exact name, or a 1-dof or 2-dof joint without its axes; it
// does not trim the names SDFormat allows to be padded with white space.
// Returns why DART cannot read `text` ("" when it can) and trims the names.
// Collects the names of static models in `static_models`.
std::string CheckSdfJoints(std::string* text, int version, std::set<std::string>* static_models) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text->c_str(), text->size()) != tinyxml2::XML_SUCCESS) {
    return std::string("tinyxml2 cannot parse it: ") + doc.ErrorStr();
  }
  std::string problem;
  ForEachModel(doc.RootElement(), [&](tinyxml2::XMLElement* m) {
    if (auto* is_static = m->FirstChildElement("static")) {
      const std::string value = Trimmed(is_static->GetText());
      if ((value == "true" || value == "1") && m->Attribute("name")) {
        static_models->insert(m->Attribute("name"));
      }
    }
    std::set<std::string> links;
    for (auto* l = m->FirstChildElement("link"); l; l = l->NextSiblingElement("link")) {
      links.insert(l->Attribute("name") ? l->Attribute("name") : "");
    }
    for (auto* j = m->FirstChildElement("joint"); j && problem.empty();
         j = j->NextSiblingElement("joint")) {
      const std::string name = j->Attribute("name") ? j->Attribute("name") : "";
      const std::string type = j->Attribute("type") ? j->Attribute("type") : "";
      for (const char* end : {"parent", "child"}) {
        tinyxml2::XMLElement* e = j->FirstChildElement(end);
        const std::string link = e ? Trimmed(e->GetText()) : "";
        if (!links.count(link) && !(link == "world" && std::strcmp(end, "parent") == 0)) {
          problem = "joint " + name + "'s " + end + " '" + link +
                    "' is not a link of its model (DART's SdfParser asserts)";
          return;
        }
        e->SetText(link.c_str());
      }
      // SDFormat 1.4 expresses axes in the model frame; libsdformat's 1.5
      // conversion says so with use_parent_model_frame, which DART reads.
      for (const char* axis : {"axis", "axis2"}) {
        tinyxml2::XMLElement* a = j->FirstChildElement(axis);
        if (version > 0 && version < 105 && a && !a->FirstChildElement("use_parent_model_frame")) {
          a->InsertNewChildElement("use_parent_model_frame")->SetText("true");
        }
      }
      const bool two_axes = type == "universal" || type == "revolute2";
      if ((two_axes || type == "revolute" || type == "prismatic" || type == "screw") &&
          (!j->FirstChildElement("axis") || (two_axes && !j->FirstChildElement("axis2")))) {
        problem = "joint " + name + " has no axis (DART's SdfParser asserts)";
      }
    }
  });
  if (!problem.empty()) return problem;
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  *text = printer.CStr();
  return "";
}

// DART 6.12's SdfParser ignores <static>: a static model's links float.
// SDFormat (and mdlc) fix them to the world where they are.
void WeldFreeRoots(dart::dynamics::Skeleton& skeleton) {
  std::vector<dart::dynamics::BodyNode*> roots;  // first: welding reorders the nodes
  for (size_t i = 0; i < skeleton.getNumBodyNodes(); ++i) {
    dart::dynamics::BodyNode* node = skeleton.getBodyNode(i);
    if (!node->getParentBodyNode() && node->getParentJoint()->getType() == "FreeJoint") {
      roots.push_back(node);
    }
  }
  for (dart::dynamics::BodyNode* node : roots) {
    const Eigen::Isometry3d X_WB = node->getWorldTransform();
    auto* weld = node->changeParentJointType<dart::dynamics::WeldJoint>();
    weld->setTransformFromChildBodyNode(Eigen::Isometry3d::Identity());
    weld->setTransformFromParentBodyNode(X_WB);
  }
}

void LoadSdf(const std::string& path, std::string text, DartModel* model) {
  if (FindStartTag(text, "include", 0) != std::string::npos) {
    model->skip_reason = "uses <include>, which DART's SdfParser does not resolve";
    return;
  }
  if (MaxModelDepth(text) > 1) {
    model->skip_reason = "has nested models, which DART's SdfParser does not read";
    return;
  }
  if (std::regex_search(text, std::regex(R"(<inertial[^>]*auto\s*=\s*["']true)"))) {
    model->skip_reason = "inertia computed from geometry (auto), which DART does not do";
    return;
  }
  size_t begin = 0, end = 0;
  const int version = SdfVersion(text, &begin, &end);
  if (version > 106) {
    for (const char* feature : {"relative_to", "expressed_in", "<frame", "placement_frame",
                                "canonical_link", "attached_to", "degrees=", "rotation_format"}) {
      if (text.find(feature) != std::string::npos) {
        model->skip_reason = "SDFormat " + text.substr(begin, end - begin) + " with '" + feature +
                             "': DART's SdfParser reads 1.4-1.6 only";
        return;
      }
    }
    model->note = "SDFormat " + text.substr(begin, end - begin) + " read as 1.6";
    text.replace(begin, end - begin, "1.6");
  }
  std::set<std::string> static_models;
  if (std::string problem = CheckSdfJoints(&text, version, &static_models); !problem.empty()) {
    model->skip_reason = problem;
    return;
  }
  const std::string uri = dart::common::Uri::createFromPath(path).toString();
  dart::utils::SdfParser::Options options(std::make_shared<TextRetriever>(uri, text));
  CaptureOutput capture;
  if (FindStartTag(text, "world", 0) != std::string::npos) {
    model->world = dart::utils::SdfParser::readWorld(dart::common::Uri(uri), options);
    if (model->world) {
      for (size_t i = 0; i < model->world->getNumSkeletons(); ++i) {
        model->skeletons.push_back(model->world->getSkeleton(i));
      }
    }
  } else if (auto skeleton = dart::utils::SdfParser::readSkeleton(dart::common::Uri(uri), options)) {
    model->skeletons.push_back(skeleton);
  }
  model->log = capture.text();
  if (model->skeletons.empty()) model->skip_reason = "DART's SdfParser reads no model from it";
  for (const auto& skeleton : model->skeletons) {
    if (static_models.count(skeleton->getName())) WeldFreeRoots(*skeleton);
  }
}

}  // namespace

DartModel LoadDartModelOrThrow(const std::string& path);

std::string StripElements(const std::string& text, const std::string& name) {
  std::string out;
  size_t from = 0;
  for (size_t at = FindStartTag(text, name, 0); at != std::string::npos;
       at = FindStartTag(text, name, from)) {
    out.append(text, from, at - from);
    const size_t gt = text.find('>', at);
    if (gt == std::string::npos) return out;  // truncated document: DART will say so
    if (text[gt - 1] == '/') {
      from = gt + 1;
      continue;
    }
    const size_t close = text.find("</" + name, gt);
    if (close == std::string::npos) return out;
    const size_t close_gt = text.find('>', close);
    from = close_gt == std::string::npos ? text.size() : close_gt + 1;
  }
  out.append(text, from, std::string::npos);
  return out;
}

std::string DartCrashesOn(const std::string& path) {
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0) return "";  // cannot tell: let the real read show
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    LoadDartModel(path);
    _exit(0);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return "";
  if (WIFSIGNALED(status)) {
    return "DART 6.12 crashes reading it (signal " + std::to_string(WTERMSIG(status)) + ")";
  }
  return "";
}

DartModel LoadDartModel(const std::string& path) {
  try {
    return LoadDartModelOrThrow(path);
  } catch (const std::exception& e) {
    DartModel model;
    model.skip_reason = std::string("DART throws reading it: ") + e.what();
    return model;
  }
}

DartModel LoadDartModelOrThrow(const std::string& path) {
  DartModel model;
  std::string text = ReadFile(path);
  if (text.empty()) {
    model.skip_reason = "cannot read the file";
    return model;
  }
  text = StripElements(StripElements(text, "visual"), "collision");
  if (EndsWith(path, ".urdf")) {
    LoadUrdf(path, std::move(text), &model);
  } else {
    LoadSdf(path, std::move(text), &model);
  }
  return model;
}

}  // namespace mdlc::oracle
