// Content-Length framing.
#include "lsp/json_rpc.h"

#include <cctype>
#include <charconv>
#include <istream>
#include <ostream>

namespace smachac::lsp {
namespace {

/// One header line without its CR LF (a bare LF is accepted); nullopt at end of input.
std::optional<std::string> readHeaderLine(std::istream& in) {
  std::string line;
  if (!std::getline(in, line)) return std::nullopt;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

std::optional<size_t> parseLength(std::string_view value) {
  while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
  while (!value.empty() && value.back() == ' ') value.remove_suffix(1);
  size_t length = 0;
  auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), length);
  if (ec != std::errc() || end != value.data() + value.size()) return std::nullopt;
  return length;
}

bool isContentLength(std::string_view name) {
  constexpr std::string_view kName = "content-length";
  if (name.size() != kName.size()) return false;
  for (size_t i = 0; i < name.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(name[i])) != kName[i]) return false;
  }
  return true;
}

}  // namespace

Frame readFrame(std::istream& in) {
  std::optional<size_t> length;
  bool any_header = false;
  while (true) {
    std::optional<std::string> line = readHeaderLine(in);
    if (!line) return {any_header ? FrameStatus::BadHeader : FrameStatus::EndOfInput, {}};
    if (line->empty()) {
      if (!any_header) continue;  // stray blank lines between messages
      break;
    }
    any_header = true;
    size_t colon = line->find(':');
    if (colon != std::string::npos && isContentLength(std::string_view(*line).substr(0, colon))) {
      length = parseLength(std::string_view(*line).substr(colon + 1));
    }
  }
  if (!length) return {FrameStatus::BadHeader, {}};
  if (*length > kMaxMessageBytes) {
    in.ignore(static_cast<std::streamsize>(*length));
    return {FrameStatus::BadHeader, {}};
  }
  std::string body(*length, '\0');
  in.read(body.data(), static_cast<std::streamsize>(*length));
  if (static_cast<size_t>(in.gcount()) != *length) return {FrameStatus::EndOfInput, {}};
  return {FrameStatus::Ok, std::move(body)};
}

void writeFrame(std::ostream& out, const Json& message) {
  std::string body = message.dump(-1, ' ', false, Json::error_handler_t::replace);
  out << "Content-Length: " << body.size() << "\r\n\r\n" << body;
  out.flush();
}

}  // namespace smachac::lsp
