// SMACHA's code buffers: the named places where the blocks rendered
// for each state collect before they flow up to the parent container and, at the root, into
// the base template. Eleven buffers are lists of snippets; `header` and `header_userdata` are
// keyed by the name of the container the snippets belong to. Later states' snippets go after
// earlier ones, except in footer, execute, base_footer and main, where they go before.
#pragma once

#include <array>
#include <cstddef>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/generator/chunked_text.h"
#include "backends/tmpl/values/value.h"

namespace smachac::generator {

enum class BufferKind : uint8_t { List, Keyed };
enum class Insertion : uint8_t { Append, Prepend };

struct BufferSpec {
  std::string_view name;
  BufferKind kind;
  Insertion insertion;  ///< where a later state's snippet goes
};

inline constexpr size_t kBufferCount = 13;

/// The buffers in SMACHA's order.
std::span<const BufferSpec, kBufferCount> bufferSpecs();

/// The index of the buffer called `name`, or nullopt.
std::optional<size_t> bufferIndex(std::string_view name);

/// The snippets of every buffer at one level of the script (the root or a container). An
/// appending buffer keeps its snippets already joined (a ChunkedText that grows, rather than a
/// string per snippet with the slack of its render), which the base render then takes whole.
class CodeBuffers {
 public:
  /// Adds a snippet to a buffer; keyed buffers file it under `container`.
  void insert(size_t buffer, std::string snippet, std::string_view container);
  /// The snippets of a list buffer joined as SMACHA does (each followed by a newline).
  std::string joined(size_t buffer) const;
  /// The keyed entries of a keyed buffer, each joined, in first-insertion order.
  std::vector<std::pair<std::string, std::string>> joinedEntries(size_t buffer) const;
  /// The buffer as a template value: a string for a list buffer, a dict of strings for a keyed
  /// one; `strip` strips every string (what the base template receives).
  tmpl::Value value(size_t buffer, bool strip) const;
  /// The same, moving the buffer's text out (the buffer is left empty): no copy of the code.
  tmpl::Value take(size_t buffer, bool strip);

 private:
  struct Keyed {
    std::string container;
    ChunkedText joined;
  };
  struct Buffer {
    ChunkedText joined;                 ///< an appending list buffer's snippets, joined
    std::deque<std::string> prepended;  ///< a prepending list buffer's snippets, latest first
    std::vector<Keyed> keyed;
  };
  std::array<Buffer, kBufferCount> buffers_;
};

/// Python's str.strip() for the ASCII whitespace templates produce.
std::string_view stripWhitespace(std::string_view text);

/// The same on `text` itself, without a copy of a large text.
void stripInPlace(std::string& text);

}  // namespace smachac::generator
