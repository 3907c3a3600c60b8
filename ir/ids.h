// Strong index types. IR entities refer to each other by id, never by pointer: state graphs
// are cyclic, and ids stay valid when stores grow.
#pragma once

#include <cstdint>
#include <limits>

namespace smachac::ir {

template <typename Tag>
struct Id {
  static constexpr uint32_t kInvalid = std::numeric_limits<uint32_t>::max();
  uint32_t index = kInvalid;

  constexpr Id() = default;
  constexpr explicit Id(uint32_t i) : index(i) {}
  constexpr bool valid() const { return index != kInvalid; }
  friend constexpr bool operator==(Id, Id) = default;
  friend constexpr auto operator<=>(Id, Id) = default;
};

using StateId = Id<struct StateTag>;

}  // namespace smachac::ir
