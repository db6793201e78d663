#include "backend/model_instance_names.h"

namespace mdlc::backend {

void ModelInstanceNames::Add(std::string local, ModelId parent) {
  entries_.push_back({std::move(local), parent});
}

void ModelInstanceNames::AppendName(size_t m, std::string& out) const {
  // the chain from the top-level ancestor down to m
  std::vector<size_t> chain;
  size_t size = out.size();
  for (size_t at = m;;) {
    chain.push_back(at);
    size += entries_[at].local.size() + 2;
    const ModelId parent = entries_[at].parent;
    if (!parent.valid() || parent.index() >= entries_.size()) break;
    at = parent.index();
  }
  out.reserve(size);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    if (it != chain.rbegin()) out += "::";
    out += entries_[*it].local;
  }
}

std::string ModelInstanceNames::operator[](size_t m) const {
  std::string out;
  AppendName(m, out);
  return out;
}

std::string ModelInstanceNames::Scoped(ModelId model, std::string_view local) const {
  std::string out;
  if (model.valid() && model.index() < entries_.size()) {
    AppendName(model.index(), out);
    out += "::";
  }
  out += local;
  return out;
}

std::vector<std::string> ModelInstanceNames::ToVector() const {
  std::vector<std::string> out;
  out.reserve(size());
  for (size_t m = 0; m < size(); ++m) out.push_back((*this)[m]);
  return out;
}

}  // namespace mdlc::backend
