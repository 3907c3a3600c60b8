// JSON-RPC 2.0 framing as the Language Server Protocol uses it on standard streams: a header
// block (`Content-Length: N`, optionally `Content-Type`), an empty line, then N bytes of JSON.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace smachac::lsp {

using Json = nlohmann::json;

/// The largest message body the server accepts (an editor sends whole documents).
inline constexpr size_t kMaxMessageBytes = 64u << 20;

enum class FrameStatus { Ok, EndOfInput, BadHeader };

struct Frame {
  FrameStatus status = FrameStatus::EndOfInput;
  std::string body;
};

/// Reads one framed message. A header block without a valid Content-Length is BadHeader; the
/// stream is then at the end of that header block.
Frame readFrame(std::istream& in);

/// Writes `message` framed, and flushes.
void writeFrame(std::ostream& out, const Json& message);

/// JSON-RPC and LSP error codes.
namespace error_code {
inline constexpr int kParseError = -32700;
inline constexpr int kInvalidRequest = -32600;
inline constexpr int kMethodNotFound = -32601;
inline constexpr int kInvalidParams = -32602;
inline constexpr int kInternalError = -32603;
inline constexpr int kServerNotInitialized = -32002;
inline constexpr int kRequestCancelled = -32800;
}  // namespace error_code

}  // namespace smachac::lsp
