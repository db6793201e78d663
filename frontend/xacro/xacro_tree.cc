#include "frontend/xacro/xacro_tree.h"

namespace mdlc::xacro {

const Attribute* Node::FindAttribute(std::string_view attribute) const {
  for (const Attribute& a : attributes) {
    if (a.name == attribute) return &a;
  }
  return nullptr;
}

Attribute* Node::FindAttribute(std::string_view attribute) {
  for (Attribute& a : attributes) {
    if (a.name == attribute) return &a;
  }
  return nullptr;
}

void Node::SetAttribute(std::string_view attribute, std::string value, Loc at) {
  if (Attribute* a = FindAttribute(attribute)) {
    a->value = std::move(value);
    return;
  }
  attributes.push_back(Attribute{std::string(attribute), std::move(value), at});
}

void Node::RemoveAttribute(std::string_view attribute) {
  for (auto it = attributes.begin(); it != attributes.end(); ++it) {
    if (it->name == attribute) {
      attributes.erase(it);
      return;
    }
  }
}

Node* Node::FirstElementChild() const {
  Node* c = first_;
  while (c && !c->is_element()) c = c->next_;
  return c;
}

Node* Node::NextElementSibling() const {
  Node* c = next_;
  while (c && !c->is_element()) c = c->next_;
  return c;
}

Node* Tree::Make(Node::Kind kind) {
  const size_t in_block = size_ % kBlockNodes;
  if (in_block == 0) blocks_.push_back(std::make_unique<Node[]>(kBlockNodes));
  Node* node = &blocks_.back()[in_block];
  ++size_;
  node->kind = kind;
  return node;
}

void Tree::AppendChild(Node* parent, Node* child) {
  Unlink(child);
  child->parent_ = parent;
  child->previous_ = parent->last_;
  if (parent->last_) {
    parent->last_->next_ = child;
  } else {
    parent->first_ = child;
  }
  parent->last_ = child;
}

void Tree::InsertBefore(Node* before, Node* node) {
  if (node == before) return;
  Unlink(node);
  Node* parent = before->parent_;
  node->parent_ = parent;
  node->next_ = before;
  node->previous_ = before->previous_;
  if (before->previous_) {
    before->previous_->next_ = node;
  } else if (parent) {
    parent->first_ = node;
  }
  before->previous_ = node;
}

void Tree::Unlink(Node* node) {
  Node* parent = node->parent_;
  if (node->previous_) {
    node->previous_->next_ = node->next_;
  } else if (parent && parent->first_ == node) {
    parent->first_ = node->next_;
  }
  if (node->next_) {
    node->next_->previous_ = node->previous_;
  } else if (parent && parent->last_ == node) {
    parent->last_ = node->previous_;
  }
  node->parent_ = node->next_ = node->previous_ = nullptr;
}

void Tree::Replace(Node* node, Node* by, bool content_only) {
  if (by == nullptr) {
    Unlink(node);
    return;
  }
  if (!content_only) {
    if (by != node) {
      InsertBefore(node, by);
      Unlink(node);
    }
    return;
  }
  // splice by's children in front of node, then drop node
  while (Node* child = by->first_) InsertBefore(node, child);
  Unlink(node);
}

}  // namespace mdlc::xacro
