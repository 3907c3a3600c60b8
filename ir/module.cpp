// Module: the state store and tree navigation.
#include "ir/module.h"

#include <utility>

namespace smachac::ir {

std::string_view targetKindName(TargetKind kind) {
  switch (kind) {
    case TargetKind::Unresolved:
      return "unresolved";
    case TargetKind::Sibling:
      return "state";
    case TargetKind::ContainerOutcome:
      return "outcome";
  }
  return "unresolved";
}

const Argument* State::findArg(std::string_view key) const {
  for (const Argument& arg : args) {
    if (arg.key.text == key) return &arg;
  }
  return nullptr;
}

StateId Module::addState(State state) {
  states_.push_back(std::move(state));
  return StateId(static_cast<uint32_t>(states_.size() - 1));
}

uint32_t Module::addBehaviorParam(StateId scope, std::string name) {
  behavior_params_.push_back({scope, std::move(name)});
  return static_cast<uint32_t>(behavior_params_.size());
}

uint32_t Module::findBehaviorParam(StateId scope, std::string_view name) const {
  for (size_t i = 0; i < behavior_params_.size(); ++i) {
    if (behavior_params_[i].scope == scope && behavior_params_[i].name == name) {
      return static_cast<uint32_t>(i + 1);
    }
  }
  return 0;
}

void Module::adopt(StateId parent, StateId child) {
  state(parent).children.push_back(child);
  state(child).parent = parent;
}

StateId Module::findChild(StateId container, std::string_view name) const {
  for (StateId child : state(container).children) {
    if (state(child).name.text == name) return child;
  }
  return StateId();
}

std::string Module::path(StateId id) const {
  std::string result = state(id).name.text;
  for (StateId p = state(id).parent; p.valid(); p = state(p).parent) {
    result = state(p).name.text + "/" + result;
  }
  return result;
}

std::vector<StateId> Module::preorder() const {
  std::vector<StateId> order;
  if (!root_.valid()) return order;
  order.reserve(states_.size());
  order.push_back(root_);
  // The containers being walked, each with the position of its next child: one frame per
  // level of nesting, not one entry per state.
  std::vector<std::pair<const std::vector<StateId>*, size_t>> walk{{&state(root_).children, 0}};
  while (!walk.empty()) {
    auto& [children, next] = walk.back();
    if (next == children->size()) {
      walk.pop_back();
      continue;
    }
    StateId id = (*children)[next++];
    order.push_back(id);
    const std::vector<StateId>& grandchildren = state(id).children;
    if (!grandchildren.empty()) walk.push_back({&grandchildren, 0});
  }
  return order;
}

}  // namespace smachac::ir
