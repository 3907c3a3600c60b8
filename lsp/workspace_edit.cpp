// Minimal text edits (a line diff narrowed to bytes) and WorkspaceEdit JSON.
#include "lsp/workspace_edit.h"

#include <algorithm>
#include <span>

#include "ir/support/check.h"

namespace smachac::lsp {
namespace {

using Lines = std::span<const std::string_view>;

/// The lines of `text`, each with its line break.
std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    end = end == std::string_view::npos ? text.size() : end + 1;
    lines.push_back(text.substr(begin, end - begin));
    begin = end;
  }
  return lines;
}

enum class Op : uint8_t { Equal, Delete, Insert };

/// The furthest x reached on each diagonal k in [-d, d] after step d of the Myers search.
class Trace {
 public:
  void record(const std::vector<long>& v, long offset, long d) {
    steps_.emplace_back(v.begin() + offset - d, v.begin() + offset + d + 1);
  }
  long at(long d, long k) const { return steps_[d][k + d]; }

 private:
  std::vector<std::vector<long>> steps_;
};

/// Whether step d reaches diagonal k by moving down (an insertion) rather than right.
bool movesDown(long d, long k, long left, long right) {
  return k == -d || (k != d && left < right);
}

/// The Myers search from (0, 0) to (n, m); the number of steps, or nullopt past `max_steps`.
std::optional<long> search(Lines a, Lines b, long max_steps, Trace& trace) {
  const long n = static_cast<long>(a.size());
  const long m = static_cast<long>(b.size());
  const long offset = max_steps + 1;
  std::vector<long> v(2 * offset + 1, 0);
  for (long d = 0; d <= max_steps; ++d) {
    bool reached_end = false;
    for (long k = -d; k <= d; k += 2) {
      long x = movesDown(d, k, v[offset + k - 1], v[offset + k + 1]) ? v[offset + k + 1]
                                                                     : v[offset + k - 1] + 1;
      long y = x - k;
      while (x < n && y < m && a[x] == b[y]) ++x, ++y;
      v[offset + k] = x;
      reached_end = reached_end || (x >= n && y >= m);
    }
    trace.record(v, offset, d);
    if (reached_end) return d;
  }
  return std::nullopt;
}

/// The edit script of a finished search, from the end back to the start, then reversed.
std::vector<Op> backtrack(const Trace& trace, long steps, long n, long m) {
  std::vector<Op> ops;
  long x = n;
  long y = m;
  for (long d = steps; d > 0; --d) {
    long k = x - y;
    // At the edges (k = ±d) only one neighbour exists and movesDown ignores the other.
    bool down = movesDown(d, k, trace.at(d - 1, std::max(k - 1, 1 - d)),
                          trace.at(d - 1, std::min(k + 1, d - 1)));
    long previous_k = down ? k + 1 : k - 1;
    long previous_x = trace.at(d - 1, previous_k);
    long snake_x = down ? previous_x : previous_x + 1;
    for (; x > snake_x; --x, --y) ops.push_back(Op::Equal);
    ops.push_back(down ? Op::Insert : Op::Delete);
    x = previous_x;
    y = previous_x - previous_k;
  }
  for (; x > 0; --x) ops.push_back(Op::Equal);
  std::reverse(ops.begin(), ops.end());
  return ops;
}

/// Old lines [old_begin, old_end) become new lines [new_begin, new_end).
struct Hunk {
  size_t old_begin = 0;
  size_t old_end = 0;
  size_t new_begin = 0;
  size_t new_end = 0;
};

std::vector<Hunk> hunksOf(const std::vector<Op>& ops, size_t old_first, size_t new_first) {
  std::vector<Hunk> hunks;
  size_t i = old_first;
  size_t j = new_first;
  for (size_t at = 0; at < ops.size();) {
    if (ops[at] == Op::Equal) {
      ++i, ++j, ++at;
      continue;
    }
    Hunk hunk{i, i, j, j};
    for (; at < ops.size() && ops[at] != Op::Equal; ++at) {
      ops[at] == Op::Delete ? ++hunk.old_end : ++hunk.new_end;
    }
    i = hunk.old_end;
    j = hunk.new_end;
    hunks.push_back(hunk);
  }
  return hunks;
}

/// The differing runs of lines: the common first and last lines set aside, a Myers diff of
/// the rest, or one run when it takes more than kMaxDiffSteps.
std::vector<Hunk> diffLines(Lines a, Lines b) {
  size_t prefix = 0;
  while (prefix < a.size() && prefix < b.size() && a[prefix] == b[prefix]) ++prefix;
  size_t suffix = 0;
  while (suffix < a.size() - prefix && suffix < b.size() - prefix &&
         a[a.size() - 1 - suffix] == b[b.size() - 1 - suffix]) {
    ++suffix;
  }
  Lines old_middle = a.subspan(prefix, a.size() - prefix - suffix);
  Lines new_middle = b.subspan(prefix, b.size() - prefix - suffix);
  if (old_middle.empty() && new_middle.empty()) return {};
  Trace trace;
  std::optional<long> steps =
      search(old_middle, new_middle, static_cast<long>(kMaxDiffSteps), trace);
  if (!steps) return {{prefix, a.size() - suffix, prefix, b.size() - suffix}};
  std::vector<Op> ops = backtrack(trace, *steps, static_cast<long>(old_middle.size()),
                                  static_cast<long>(new_middle.size()));
  return hunksOf(ops, prefix, prefix);
}

/// Whether a boundary at `at` would split a UTF-8 sequence or a CRLF line break.
bool splitsText(std::string_view text, size_t at) {
  if (at == 0 || at >= text.size()) return false;
  bool continuation = (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80;
  return continuation || (text[at - 1] == '\r' && text[at] == '\n');
}

/// Byte ranges [begin, end) of a change, in the old and in the new text.
struct ByteChange {
  size_t old_begin = 0;
  size_t old_end = 0;
  size_t new_begin = 0;
  size_t new_end = 0;
};

/// The change without its common first and last bytes, cut at safe boundaries.
ByteChange narrow(std::string_view before, std::string_view after, ByteChange c) {
  size_t limit = std::min(c.old_end - c.old_begin, c.new_end - c.new_begin);
  size_t prefix = 0;
  while (prefix < limit && before[c.old_begin + prefix] == after[c.new_begin + prefix]) ++prefix;
  while (prefix > 0 &&
         (splitsText(before, c.old_begin + prefix) || splitsText(after, c.new_begin + prefix))) {
    --prefix;
  }
  size_t suffix = 0;
  while (suffix < limit - prefix &&
         before[c.old_end - 1 - suffix] == after[c.new_end - 1 - suffix]) {
    ++suffix;
  }
  while (suffix > 0 &&
         (splitsText(before, c.old_end - suffix) || splitsText(after, c.new_end - suffix))) {
    --suffix;
  }
  return {c.old_begin + prefix, c.old_end - suffix, c.new_begin + prefix, c.new_end - suffix};
}

/// The byte offset of each line's start, and of the end of the text last.
std::vector<size_t> lineOffsets(const std::vector<std::string_view>& lines) {
  std::vector<size_t> offsets{0};
  for (std::string_view line : lines) offsets.push_back(offsets.back() + line.size());
  return offsets;
}

/// The position of an offset. The end of a text that ends with `\r` is past its last line:
/// LineIndex counts that `\r` as part of a line break and has no position after it.
Position positionAt(std::string_view text, const LineIndex& index, size_t offset) {
  if (offset == text.size() && !text.empty() && text.back() == '\r') {
    return {index.lineCount(), 0};
  }
  return index.positionOf(offset);
}

}  // namespace

std::vector<TextEdit> diffEdits(std::string_view before, std::string_view after) {
  std::vector<std::string_view> old_lines = splitLines(before);
  std::vector<std::string_view> new_lines = splitLines(after);
  std::vector<size_t> old_offsets = lineOffsets(old_lines);
  std::vector<size_t> new_offsets = lineOffsets(new_lines);
  LineIndex index(before);
  std::vector<TextEdit> edits;
  for (const Hunk& hunk : diffLines(old_lines, new_lines)) {
    ByteChange change{old_offsets[hunk.old_begin], old_offsets[hunk.old_end],
                      new_offsets[hunk.new_begin], new_offsets[hunk.new_end]};
    bool one_line = hunk.old_end - hunk.old_begin == 1 && hunk.new_end - hunk.new_begin == 1;
    if (one_line) change = narrow(before, after, change);
    Range range{positionAt(before, index, change.old_begin),
                positionAt(before, index, change.old_end)};
    edits.push_back(
        {range, std::string(after.substr(change.new_begin, change.new_end - change.new_begin))});
  }
  return edits;
}

Json toJson(const TextEdit& edit) {
  return {{"range", toJson(edit.range)}, {"newText", edit.new_text}};
}

EditSupport editSupport(const Json& client_capabilities) {
  Json::json_pointer edit("/workspace/workspaceEdit");
  if (!client_capabilities.contains(edit) || !client_capabilities.at(edit).is_object()) return {};
  const Json& capabilities = client_capabilities.at(edit);
  EditSupport support;
  support.document_changes = capabilities.value("documentChanges", Json()) == true;
  Json operations = capabilities.value("resourceOperations", Json());
  support.create_files = operations.is_array() && std::find(operations.begin(), operations.end(),
                                                            "create") != operations.end();
  return support;
}

void WorkspaceEdit::createFile(const std::string& uri) {
  SMACHAC_CHECK(canCreateFiles(), "a file is created only when the client can");
  changes_.push_back({uri, true, std::nullopt, {}});
}

void WorkspaceEdit::editDocument(const std::string& uri, std::optional<int64_t> version,
                                 std::vector<TextEdit> edits) {
  changes_.push_back({uri, false, version, std::move(edits)});
}

Json WorkspaceEdit::toJson() const {
  if (!support_.document_changes) {
    Json by_uri = Json::object();
    for (const Change& change : changes_) {
      Json& edits = by_uri[change.uri];
      if (edits.is_null()) edits = Json::array();
      for (const TextEdit& edit : change.edits) edits.push_back(lsp::toJson(edit));
    }
    return {{"changes", std::move(by_uri)}};
  }
  Json document_changes = Json::array();
  for (const Change& change : changes_) {
    if (change.create) {
      document_changes.push_back({{"kind", "create"}, {"uri", change.uri}});
      continue;
    }
    Json edits = Json::array();
    for (const TextEdit& edit : change.edits) edits.push_back(lsp::toJson(edit));
    Json version = change.version ? Json(*change.version) : Json(nullptr);
    document_changes.push_back(
        {{"textDocument", {{"uri", change.uri}, {"version", version}}}, {"edits", edits}});
  }
  return {{"documentChanges", std::move(document_changes)}};
}

}  // namespace smachac::lsp
