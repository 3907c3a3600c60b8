// Lookup in the precompiled meta table (builtin_meta.h).
#include "templates/builtin_meta.h"

#include <algorithm>

namespace smachac::templates {

const BuiltinMeta* findBuiltinMeta(std::string_view path) {
  std::span<const BuiltinMeta> metas = builtinMetas();
  auto it = std::lower_bound(metas.begin(), metas.end(), path,
                             [](const BuiltinMeta& m, std::string_view p) { return m.path < p; });
  return it != metas.end() && it->path == path ? &*it : nullptr;
}

}  // namespace smachac::templates
