// The code buffers and SMACHA's joining rules.
#include "backends/generator/code_buffers.h"

#include <algorithm>
#include <utility>

namespace smachac::generator {
namespace {

constexpr std::array<BufferSpec, kBufferCount> kSpecs = {{
    {"base_header", BufferKind::List, Insertion::Append},
    {"imports", BufferKind::List, Insertion::Append},
    {"defs", BufferKind::List, Insertion::Append},
    {"class_defs", BufferKind::List, Insertion::Append},
    {"cb_defs", BufferKind::List, Insertion::Append},
    {"main_def", BufferKind::List, Insertion::Append},
    {"header", BufferKind::Keyed, Insertion::Append},
    {"header_userdata", BufferKind::Keyed, Insertion::Append},
    {"body", BufferKind::List, Insertion::Append},
    {"footer", BufferKind::List, Insertion::Prepend},
    {"execute", BufferKind::List, Insertion::Prepend},
    {"base_footer", BufferKind::List, Insertion::Prepend},
    {"main", BufferKind::List, Insertion::Prepend},
}};

template <class Snippets>
std::string joinSnippets(const Snippets& snippets) {
  size_t size = 0;
  for (const std::string& s : snippets) size += s.size() + 1;
  std::string out;
  out.reserve(size);
  for (const std::string& s : snippets) {
    out += s;
    out += '\n';
  }
  return out;
}

/// SMACHA's join, one snippet at a time: the snippet and a newline.
void appendSnippet(ChunkedText& joined, std::string_view snippet) {
  joined.append(snippet);
  joined.append("\n");
}

tmpl::Value stringValue(std::string text, bool strip) {
  if (strip) stripInPlace(text);
  return tmpl::Value::string(std::move(text));
}

}  // namespace

std::span<const BufferSpec, kBufferCount> bufferSpecs() { return kSpecs; }

std::optional<size_t> bufferIndex(std::string_view name) {
  for (size_t i = 0; i < kSpecs.size(); ++i) {
    if (kSpecs[i].name == name) return i;
  }
  return std::nullopt;
}

void CodeBuffers::insert(size_t buffer, std::string snippet, std::string_view container) {
  const BufferSpec& spec = kSpecs[buffer];
  Buffer& b = buffers_[buffer];
  if (spec.kind == BufferKind::Keyed) {
    auto entry = std::find_if(b.keyed.begin(), b.keyed.end(),
                              [&](const Keyed& k) { return k.container == container; });
    if (entry == b.keyed.end()) entry = b.keyed.insert(entry, {std::string(container), {}});
    appendSnippet(entry->joined, snippet);
  } else if (spec.insertion == Insertion::Prepend) {
    snippet.shrink_to_fit();  // kept until the end: without the slack of its render
    b.prepended.push_front(std::move(snippet));
  } else {
    appendSnippet(b.joined, snippet);
  }
}

std::string CodeBuffers::joined(size_t buffer) const {
  const Buffer& b = buffers_[buffer];
  return kSpecs[buffer].insertion == Insertion::Prepend ? joinSnippets(b.prepended)
                                                        : b.joined.joined();
}

std::vector<std::pair<std::string, std::string>> CodeBuffers::joinedEntries(size_t buffer) const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const Keyed& entry : buffers_[buffer].keyed) {
    out.emplace_back(entry.container, entry.joined.joined());
  }
  return out;
}

tmpl::Value CodeBuffers::value(size_t buffer, bool strip) const {
  if (kSpecs[buffer].kind == BufferKind::List) return stringValue(joined(buffer), strip);
  tmpl::Value dict = tmpl::Value::newDict();
  for (auto& [container, code] : joinedEntries(buffer)) {
    dict.dict().setString(container, stringValue(std::move(code), strip));
  }
  return dict;
}

tmpl::Value CodeBuffers::take(size_t buffer, bool strip) {
  Buffer& b = buffers_[buffer];
  if (kSpecs[buffer].kind == BufferKind::Keyed) {
    tmpl::Value dict = tmpl::Value::newDict();
    for (Keyed& entry : b.keyed) {
      dict.dict().setString(entry.container, stringValue(entry.joined.take(), strip));
    }
    b.keyed.clear();
    return dict;
  }
  if (kSpecs[buffer].insertion == Insertion::Prepend) {
    std::string code = joinSnippets(b.prepended);
    b.prepended.clear();
    return stringValue(std::move(code), strip);
  }
  return stringValue(b.joined.take(), strip);
}

void stripInPlace(std::string& text) {
  std::string_view kept = stripWhitespace(text);
  size_t first = kept.empty() ? 0 : static_cast<size_t>(kept.data() - text.data());
  text.resize(first + kept.size());
  text.erase(0, first);
}

std::string_view stripWhitespace(std::string_view text) {
  constexpr std::string_view kSpace = " \t\n\r\f\v";
  size_t first = text.find_first_not_of(kSpace);
  if (first == std::string_view::npos) return {};
  size_t last = text.find_last_not_of(kSpace);
  return text.substr(first, last - first + 1);
}

}  // namespace smachac::generator
