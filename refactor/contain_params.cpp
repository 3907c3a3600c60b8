// contain: lifting params into the container.
#include "refactor/contain_params.h"

#include <fmt/core.h>

#include "refactor/lookup_rewrite.h"

namespace smachac::refactor {
namespace {

class ParamLifter {
 public:
  explicit ParamLifter(const ContainScope& scope) : scope_(scope) {}

  std::vector<ContainerParam> run() {
    for (size_t i = scope_.selection.first; i <= scope_.selection.last(); ++i) liftFrom(i);
    return std::move(params_);
  }

 private:
  const ContainerParam* find(std::string_view key) const {
    for (const ContainerParam& p : params_) {
      if (p.key == key) return &p;
    }
    return nullptr;
  }

  std::string freshKey(const std::string& key, const ir::Value& own) const {
    for (size_t n = 1;; ++n) {
      std::string candidate = fmt::format("{}_{}", key, n);
      if (!find(candidate) && !own.find(candidate)) return candidate;
    }
  }

  void liftFrom(size_t index) {
    const ir::Value& body = scope_.root(index).body();
    std::optional<size_t> at = findKeyIndex(body, "params");
    if (!at || !body.asMap()[*at].value.isMap()) return;
    const ir::Value& own = body.asMap()[*at].value;
    Renames renames;
    std::vector<size_t> lifted;
    for (size_t j = 0; j < own.asMap().size(); ++j) {
      const ir::MapEntry& param = own.asMap()[j];
      if (liftOne(index, body, own, param, renames)) lifted.push_back(j);
    }
    renameParamLookups(scope_.text(), scope_.edits, body, renames);
    if (lifted.size() == own.asMap().size()) {
      scope_.deletions.add(body, *at);
    } else {
      scope_.deletions.add(own, lifted);
    }
  }

  bool liftOne(size_t index, const ir::Value& body, const ir::Value& own, const ir::MapEntry& param,
               Renames& renames) {
    Span span = entryValueSpan(scope_.text(), own, param);
    const ContainerParam* existing = find(param.key);
    if (!existing) {
      params_.push_back({param.key, &param.value, span});
      return true;
    }
    if (ir::sameValue(*existing->value, param.value)) return true;
    if (std::optional<std::string> script = subScriptInheriting(body, param.key)) {
      scope_.diags.emit<DiagKind::ParamNotLifted>(param.key_loc, param.key,
                                                  scope_.root(index).name(), param.key, *script);
      return false;
    }
    std::string key = freshKey(param.key, own);
    renames.emplace(param.key, key);
    params_.push_back({key, &param.value, span});
    return true;
  }

  const ContainScope& scope_;
  std::vector<ContainerParam> params_;
};

}  // namespace

std::vector<ContainerParam> liftParams(const ContainScope& scope) {
  return ParamLifter(scope).run();
}

}  // namespace smachac::refactor
