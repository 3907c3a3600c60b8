// libFuzzer harness: the language server in-process (lsp::Server on string streams). The
// first byte chooses how the rest is read:
//   * even: the rest is the server's input as it is, framed messages or not (seeds are whole
//     sessions); the server must end without crashing or hanging
//   * odd: the rest is a program of edits and requests (Program below) on one document,
//     turned into well-formed messages; then, besides not crashing, the server must answer
//     every request it was sent (a result or an error), shutdown included
// Any crash, hang, sanitizer report, failed SMACHAC_CHECK or unanswered request is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "lsp/json_rpc.h"
#include "lsp/server.h"

namespace {

using smachac::lsp::Json;

constexpr const char* kUri = "file:///nonexistent-smachac-fuzz/doc.yml";

const std::vector<std::string>& requestMethods() {
  static const std::vector<std::string> kMethods = {
#define SMACHAC_LSP_REQUEST(method, function) method,
#include "lsp/requests.def"
  };
  return kMethods;
}

/// Reads the fuzzer's bytes as small numbers and texts; zeros past the end.
class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  bool done() const { return at_ >= size_; }
  uint8_t next() { return at_ < size_ ? data_[at_++] : 0; }
  /// A length (two bytes when `max_length` needs them), then that many bytes.
  std::string text(size_t max_length) {
    size_t raw = next();
    if (max_length > 255) raw = raw << 8 | next();
    size_t length = std::min<size_t>(raw % (max_length + 1), size_ - std::min(at_, size_));
    std::string out(reinterpret_cast<const char*>(data_ + at_), length);
    at_ += length;
    return out;
  }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t at_ = 0;
};

/// Turns the bytes into a session: initialize, didOpen, then one operation per step.
class Program {
 public:
  explicit Program(Bytes bytes) : bytes_(bytes) {}

  std::string session() {
    request("initialize", {{"capabilities", capabilities(bytes_.next() % 2 == 1)}});
    notify("initialized", Json::object());
    open(bytes_.text(4096));
    while (!bytes_.done()) step();
    request("shutdown", nullptr);
    notify("exit", nullptr);
    return out_.str();
  }

  const std::set<int64_t>& requests() const { return requests_; }

 private:
  static Json capabilities(bool rich) {
    if (!rich) return Json::object();
    return {{"textDocument",
             {{"codeAction", {{"codeActionLiteralSupport", Json::object()}}},
              {"documentSymbol", {{"hierarchicalDocumentSymbolSupport", true}}}}},
            {"workspace",
             {{"workspaceEdit", {{"documentChanges", true}, {"resourceOperations", {"create"}}}}}}};
  }

  Json position() { return {{"line", bytes_.next() % 48}, {"character", bytes_.next() % 96}}; }

  void step() {
    switch (bytes_.next() % 6) {
      case 0:
        return change(
            {{"range", {{"start", position()}, {"end", position()}}}, {"text", bytes_.text(24)}});
      case 1:
        return change({{"text", bytes_.text(1024)}});
      case 2:
        return notify("$/cancelRequest", {{"id", next_id_ - 1}});
      case 3:
        notify("textDocument/didClose", {{"textDocument", {{"uri", kUri}}}});
        return open(bytes_.text(1024));
      default:
        return ask();
    }
  }

  void ask() {
    const std::vector<std::string>& methods = requestMethods();
    if (methods.empty()) return;
    const std::string& method = methods[bytes_.next() % methods.size()];
    Json context = {{"diagnostics", Json::array()}, {"includeDeclaration", true}};
    if (bytes_.next() % 4 == 0) context["only"] = {"refactor"};
    Json start = position();
    request(method, {{"textDocument", {{"uri", kUri}}},
                     {"position", start},
                     {"range", {{"start", start}, {"end", position()}}},
                     {"context", context},
                     {"newName", "RENAMED"},
                     {"query", ""}});
  }

  void open(const std::string& text) {
    notify("textDocument/didOpen",
           {{"textDocument",
             {{"uri", kUri}, {"languageId", "yaml"}, {"version", ++version_}, {"text", text}}}});
  }

  void change(Json content_change) {
    notify("textDocument/didChange",
           {{"textDocument", {{"uri", kUri}, {"version", ++version_}}},
            {"contentChanges", Json::array({std::move(content_change)})}});
  }

  void request(const std::string& method, Json params) {
    requests_.insert(next_id_);
    write({{"jsonrpc", "2.0"}, {"id", next_id_++}, {"method", method}, {"params", params}});
  }

  void notify(const std::string& method, Json params) {
    write({{"jsonrpc", "2.0"}, {"method", method}, {"params", params}});
  }

  void write(const Json& message) {
    // Fuzzed texts are not always UTF-8: invalid bytes become U+FFFD, as an editor sends them.
    std::string body = message.dump(-1, ' ', false, Json::error_handler_t::replace);
    out_ << "Content-Length: " << body.size() << "\r\n\r\n" << body;
  }

  Bytes bytes_;
  std::ostringstream out_;
  std::set<int64_t> requests_;
  int64_t next_id_ = 1;
  int64_t version_ = 0;
};

std::string serve(std::string input) {
  std::istringstream in(std::move(input));
  std::ostringstream out;
  smachac::lsp::Server server(in, out, {});
  server.run();
  return out.str();
}

/// The ids of the responses in the server's output.
std::set<int64_t> answered(const std::string& output) {
  std::istringstream in(output);
  std::set<int64_t> ids;
  for (smachac::lsp::Frame frame = smachac::lsp::readFrame(in);
       frame.status == smachac::lsp::FrameStatus::Ok; frame = smachac::lsp::readFrame(in)) {
    Json message = Json::parse(frame.body, nullptr, false);
    if (message.is_object() && !message.contains("method") && message["id"].is_number_integer()) {
      ids.insert(message["id"].get<int64_t>());
    }
  }
  return ids;
}

/// Built-in templates' copies (a definition on `template:`) go to a temporary cache, not the
/// user's; it is removed when the fuzzer exits.
char cache_directory[] = "/tmp/smachac_lsp_fuzzer_XXXXXX";

void removeTemporaryCache() {
  std::error_code ignored;
  std::filesystem::remove_all(cache_directory, ignored);
}

bool useTemporaryCache() {
  if (mkdtemp(cache_directory) == nullptr) return false;
  std::atexit(removeTemporaryCache);
  return setenv("XDG_CACHE_HOME", cache_directory, 1) == 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool kCacheReady = useTemporaryCache();
  (void)kCacheReady;
  if (size == 0) return 0;
  if (data[0] % 2 == 0) {
    serve(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
    return 0;
  }
  Program program(Bytes(data + 1, size - 1));
  std::string session = program.session();
  std::set<int64_t> ids = answered(serve(std::move(session)));
  for (int64_t id : program.requests()) {
    if (!ids.contains(id)) __builtin_trap();  // a request without an answer
  }
  return 0;
}
