// State ids: two 64-bit FNV-1a hashes with different seeds, each finished with the
// SplitMix64 mixer, formatted as a UUID4.
#include "backends/generator/state_uuid.h"

#include <cstdint>

namespace smachac::generator {
namespace {

/// The two hashes, of the same bytes, computed in one pass.
struct HashPair {
  uint64_t first = 0xcbf29ce484222325ULL;
  uint64_t second = 0x84222325cbf29ce4ULL;

  void add(unsigned char c) {
    constexpr uint64_t kPrime = 0x100000001b3ULL;
    first = (first ^ c) * kPrime;
    second = (second ^ c) * kPrime;
  }
};

HashPair fnv1a(std::string_view a, std::string_view b) {
  HashPair h;
  for (unsigned char c : a) h.add(c);
  h.add(0xffU);  // separator: no file name / path split collides with another
  for (unsigned char c : b) h.add(c);
  return h;
}

uint64_t mix(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

void writeHex(char* out, uint64_t v) {
  constexpr char kDigits[] = "0123456789abcdef";
  for (int shift = 60; shift >= 0; shift -= 4) *out++ = kDigits[(v >> shift) & 0xf];
}

std::string_view baseName(std::string_view path) {
  size_t slash = path.find_last_of("/\\");
  return slash == std::string_view::npos ? path : path.substr(slash + 1);
}

}  // namespace

std::string stateUuid(std::string_view script_path, std::string_view state_path) {
  std::string_view file = baseName(script_path);
  HashPair h = fnv1a(file, state_path);
  std::string hex(32, '0');
  writeHex(hex.data(), mix(h.first));
  writeHex(hex.data() + 16, mix(h.second));
  hex[12] = '4';
  constexpr char kVariant[] = "89ab";
  hex[16] = kVariant[(hex[16] <= '9' ? hex[16] - '0' : hex[16] - 'a' + 10) & 3];
  return hex;
}

}  // namespace smachac::generator
