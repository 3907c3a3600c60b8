// The static type of the userdata keys a container's children see, from the literals (as
// check-userdata-types reads them): a key's type is ir::Type::ofValue of its effective literal
// (the last `userdata` entry for it in the scope, UserdataScope's order); an input key of the
// container without one has the type of the parent's key it is copied from; any other key the
// scope knows (written by a child, read from outside) is `any`. Tables are built on first use.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "ir/module.h"
#include "ir/type.h"

namespace smachac::passes {

class KeyTypes {
 public:
  explicit KeyTypes(const ir::Module& module) : module_(module) {}

  /// The type of `key` in the scope of `container`, or nullopt when the scope has no such key.
  std::optional<ir::Type> find(ir::StateId container, std::string_view key);

 private:
  using Table = std::unordered_map<std::string, ir::Type>;
  const Table& table(ir::StateId container);
  Table build(ir::StateId container);

  const ir::Module& module_;
  std::unordered_map<uint32_t, Table> tables_;
};

}  // namespace smachac::passes
