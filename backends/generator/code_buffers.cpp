// The code buffers and SMACHA's joining rules.
#include "backends/generator/code_buffers.h"

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
    for (Keyed& entry : b.keyed) {
      if (entry.container == container) {
        entry.snippets.push_back(std::move(snippet));
        return;
      }
    }
    b.keyed.push_back({std::string(container), {std::move(snippet)}});
  } else if (spec.insertion == Insertion::Prepend) {
    b.snippets.push_front(std::move(snippet));
  } else {
    b.snippets.push_back(std::move(snippet));
  }
}

std::string CodeBuffers::joined(size_t buffer) const {
  return joinSnippets(buffers_[buffer].snippets);
}

std::vector<std::pair<std::string, std::string>> CodeBuffers::joinedEntries(size_t buffer) const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const Keyed& entry : buffers_[buffer].keyed) {
    out.emplace_back(entry.container, joinSnippets(entry.snippets));
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
