// The precompiled image of a template: its parsed and scope-analysed AST as bytes, which the
// build writes for every built-in template (image_writer.h, tools/cmake/embed_gen.cpp) and a
// compile loads into the template's arena instead of parsing (image_reader.h).
//
// Layout (integers are LEB128 varints unless fixed; fixed ones little-endian):
//   header   "SMTI", version byte, u32 source size, u64 imageHash(source),
//            u64 imageHash(everything after the header)
//   strings  count, each one's length, then their bytes one after another; every name, attribute,
//            constant string, filter and test name and template reference is an index into it
//   filters  count, string index of each filter name; tests likewise (nodes name them by index)
//   template flags (1 has_extends, 2 names_templates), references (count, string, pos),
//            block count, root frame, root body
// Nodes: a statement or expression is its kind byte (StmtKind / ExprKind; kNullNode for an
// absent expression), its position, then its fields in ast.h's order (image_writer.cpp is the
// reference). A slot reference is valid byte, up, slot; an int slot (-1 for none) is stored +1;
// a frame layout is slot count, capturable byte, then each init (kind byte, slot, name, alias).
// A top-level macro that the parser would defer (parser/deferred_macro.cpp) keeps its header
// (name, target, toplevel) in place and its signature, body, frame and slots in a record
// prefixed by its byte size, which the loader skips and reads on the macro's first call.
// Rules: the same AST gives the same bytes (deterministic: strings in order of first use);
// anything that does not fit (magic, version, sizes, hashes, a kind, an index, a text outside
// the source, a filter or test the registry lacks) refuses the whole image, and the template is
// compiled from its source as before. The hash reads 8-byte words in the machine's order, so
// a machine of the other byte order refuses the build's images and compiles.
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>

namespace smachac::tmpl::image {

inline constexpr char kMagic[4] = {'S', 'M', 'T', 'I'};
inline constexpr uint8_t kVersion = 1;
inline constexpr size_t kHeaderSize = 4 + 1 + 4 + 8 + 8;
inline constexpr uint8_t kNullNode = 0xff;
inline constexpr uint8_t kHasExtends = 1;
inline constexpr uint8_t kNamesTemplates = 2;

/// Constant kinds of a ConstExpr.
enum class ConstKind : uint8_t { None, False, True, Int, Float, String };

/// A fast hash of bytes: four lanes of 8-byte words, each step `(lane ^ word) * odd`, a
/// bijection of the lane, so that an image of another source or with any one word changed gets
/// another hash (not a defence against crafted input: the image is part of the binary).
inline uint64_t imageHash(std::string_view bytes) {
  constexpr uint64_t kOdd = 0xff51afd7ed558ccdull;
  uint64_t lanes[4] = {bytes.size(), 1, 2, 3};
  size_t i = 0;
  auto word = [&](size_t at) {
    uint64_t w;
    std::memcpy(&w, bytes.data() + at, 8);
    return w;
  };
  for (; i + 32 <= bytes.size(); i += 32) {
    for (int lane = 0; lane < 4; ++lane) lanes[lane] = (lanes[lane] ^ word(i + 8 * lane)) * kOdd;
  }
  for (; i + 8 <= bytes.size(); i += 8) lanes[0] = (lanes[0] ^ word(i)) * kOdd;
  uint64_t tail = 0;
  for (size_t shift = 0; i < bytes.size(); ++i, shift += 8) {
    tail |= uint64_t(static_cast<uint8_t>(bytes[i])) << shift;
  }
  uint64_t hash = (lanes[0] ^ tail) * kOdd;
  for (int lane = 1; lane < 4; ++lane) {
    hash ^= hash >> 29;
    hash = (hash ^ lanes[lane]) * kOdd;
  }
  return hash ^ (hash >> 29);
}

}  // namespace smachac::tmpl::image
