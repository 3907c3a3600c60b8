// The server loop: lifecycle, dispatch, document sync and configuration.
#include "lsp/server.h"

#include <istream>
#include <thread>

#include "lsp/capabilities.h"
#include "lsp/features/diagnostics.h"
#include "lsp/features/features.h"
#include "lsp/uri.h"

namespace smachac::lsp {
namespace {

using RequestHandler = Json (*)(Workspace&, const Json&);

const std::map<std::string, RequestHandler, std::less<>>& requestHandlers() {
  static const std::map<std::string, RequestHandler, std::less<>> kHandlers = {
#define SMACHAC_LSP_REQUEST(method, function) {method, &function},
#include "lsp/requests.def"
  };
  return kHandlers;
}

const Json& member(const Json& object, const char* key) {
  static const Json kNull;
  if (!object.is_object()) return kNull;
  auto it = object.find(key);
  return it == object.end() ? kNull : *it;
}

/// The workspace folders of an initialize request (or its root URI) as paths.
std::vector<std::string> workspaceRoots(const Json& params) {
  std::vector<std::string> roots;
  const Json& folders = member(params, "workspaceFolders");
  if (folders.is_array()) {
    for (const Json& folder : folders) {
      const Json& uri = member(folder, "uri");
      if (!uri.is_string()) continue;
      if (std::optional<std::string> path = pathFromUri(uri.get<std::string>())) {
        roots.push_back(*path);
      }
    }
  }
  const Json& root = member(params, "rootUri");
  if (roots.empty() && root.is_string()) {
    if (std::optional<std::string> path = pathFromUri(root.get<std::string>())) {
      roots.push_back(*path);
    }
  }
  return roots;
}

std::string uriOf(const Json& params) {
  return member(params, "textDocument").at("uri").get<std::string>();
}

}  // namespace

Server::Server(std::istream& in, std::ostream& out, Settings settings)
    : in_(in), out_(out), workspace_(std::move(settings)) {
  // A tied input stream flushes its output stream before each read: on the reader thread,
  // that flush would race with the server loop's writes.
  in_.tie(nullptr);
}

int Server::run() {
  std::thread reader([this] { readMessages(); });
  while (!exited_) {
    if (queue_.empty()) publishStale();
    Incoming incoming = queue_.pop();
    if (incoming.kind == Incoming::Kind::End) break;
    if (incoming.kind == Incoming::Kind::ParseError) {
      replyError(nullptr, error_code::kParseError, "the message is not valid JSON");
      continue;
    }
    handle(incoming.message);
  }
  reader.join();
  return exited_ && phase_ == Phase::ShutDown ? 0 : 1;
}

void Server::readMessages() {
  while (true) {
    Frame frame = readFrame(in_);
    if (frame.status == FrameStatus::EndOfInput) break;
    if (frame.status == FrameStatus::BadHeader) {
      queue_.push({Incoming::Kind::ParseError, {}});
      continue;
    }
    Json message = Json::parse(frame.body, nullptr, false);
    if (message.is_discarded()) {
      queue_.push({Incoming::Kind::ParseError, {}});
      continue;
    }
    const Json& method = member(message, "method");
    if (method == "$/cancelRequest") queue_.cancel(member(member(message, "params"), "id"));
    bool is_exit = method == "exit";  // `method` is gone once the message is queued
    queue_.push({Incoming::Kind::Message, std::move(message)});
    if (is_exit) return;  // nothing is read after exit
  }
  queue_.push({Incoming::Kind::End, {}});
}

void Server::handle(const Json& message) {
  const Json& method = member(message, "method");
  if (!message.is_object() || (!method.is_null() && !method.is_string())) {
    replyError(member(message, "id"), error_code::kInvalidRequest, "not a JSON-RPC message");
    return;
  }
  if (method.is_null()) return handleResponse(message);
  const Json& params = member(message, "params");
  if (message.contains("id")) {
    return handleRequest(message["id"], method.get<std::string>(), params);
  }
  handleNotification(method.get<std::string>(), params);
}

void Server::handleRequest(const Json& id, const std::string& method, const Json& params) {
  if (queue_.takeCancelled(id)) {
    return replyError(id, error_code::kRequestCancelled, "the request was cancelled");
  }
  if (phase_ == Phase::Uninitialized && method != "initialize") {
    return replyError(id, error_code::kServerNotInitialized, "the server is not initialized");
  }
  if (phase_ == Phase::ShutDown) {
    return replyError(id, error_code::kInvalidRequest, "the server is shut down");
  }
  if (method != "initialize" && method != "shutdown" && !requestHandlers().contains(method)) {
    return replyError(id, error_code::kMethodNotFound, "unknown method `" + method + "`");
  }
  try {
    reply(id, answer(method, params));
  } catch (const Json::exception& e) {
    replyError(id, error_code::kInvalidParams, std::string("invalid params: ") + e.what());
  } catch (const std::exception& e) {
    replyError(id, error_code::kInternalError, e.what());
  }
}

Json Server::answer(const std::string& method, const Json& params) {
  if (method == "initialize") {
    if (phase_ != Phase::Uninitialized) throw std::runtime_error("initialize was sent twice");
    applySettings(member(params, "initializationOptions"));
    workspace_.setClientCapabilities(member(params, "capabilities"));
    workspace_.setRoots(workspaceRoots(params));
    const Json& workspace = member(member(params, "capabilities"), "workspace");
    client_has_configuration_ = member(workspace, "configuration") == true;
    phase_ = Phase::Running;
    return initializeResult();
  }
  if (method == "shutdown") {
    phase_ = Phase::ShutDown;
    return nullptr;
  }
  return requestHandlers().at(method)(workspace_, params);
}

void Server::handleNotification(const std::string& method, const Json& params) {
  if (method == "exit") {
    exited_ = true;
    return;
  }
  if (phase_ != Phase::Running) return;  // notifications before initialize are dropped
  try {
    if (method == "initialized") return initialized();
    if (method == "textDocument/didOpen") {
      const Json& document = params.at("textDocument");
      std::string uri = document.at("uri").get<std::string>();
      workspace_.documents().open(uri, document.at("text").get<std::string>(),
                                  document.value("version", int64_t{0}));
      return workspace_.opened(uri);
    }
    if (method == "textDocument/didChange") {
      std::string uri = uriOf(params);
      int64_t version = member(params, "textDocument").value("version", int64_t{0});
      if (workspace_.documents().change(uri, version, member(params, "contentChanges"))) {
        workspace_.changed(uri);
      }
      return;
    }
    if (method == "textDocument/didClose") {
      std::string uri = uriOf(params);
      workspace_.documents().close(uri);
      return workspace_.closed(uri);
    }
    if (method == "workspace/didChangeConfiguration") {
      const Json& section = member(member(params, "settings"), "smachac");
      if (!section.is_null()) return applySettings(section);
      if (client_has_configuration_) requestConfiguration();
      return;
    }
    if (method == "workspace/didChangeWatchedFiles" || method == "textDocument/didSave") {
      return workspace_.filesChanged();
    }
  } catch (const Json::exception&) {
    // A malformed notification has no answer; it changes nothing.
  }
}

void Server::handleResponse(const Json& message) {
  const Json& id = member(message, "id");
  if (!id.is_number_integer()) return;
  auto it = pending_.find(id.get<int64_t>());
  if (it == pending_.end()) return;
  ResponseHandler on_response = std::move(it->second);
  pending_.erase(it);
  on_response(message);
}

void Server::initialized() {
  if (client_has_configuration_) requestConfiguration();
}

void Server::requestConfiguration() {
  Json params = {{"items", Json::array({{{"section", "smachac"}}})}};
  request("workspace/configuration", std::move(params), [this](const Json& response) {
    const Json& result = member(response, "result");
    if (result.is_array() && !result.empty()) applySettings(result[0]);
  });
}

void Server::applySettings(const Json& json) {
  Settings settings = workspace_.settings();
  if (std::optional<std::string> error = lsp::applySettings(settings, json)) {
    return showError("smachac: " + *error);
  }
  workspace_.setSettings(std::move(settings));
}

void Server::publishStale() {
  for (const std::string& uri : workspace_.takeClosed()) {
    notify("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", Json::array()}});
  }
  for (const std::string& uri : workspace_.takeStale()) {
    if (const Analysis* analysis = workspace_.analysis(uri)) {
      notify("textDocument/publishDiagnostics", publishDiagnosticsParams(*analysis));
    }
  }
  for (const auto& analysis : workspace_.takeClosedDependents()) {
    notify("textDocument/publishDiagnostics", publishDiagnosticsParams(*analysis));
  }
}

void Server::reply(const Json& id, Json result) {
  writeFrame(out_, {{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
}

void Server::replyError(const Json& id, int code, const std::string& message) {
  writeFrame(out_,
             {{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}});
}

void Server::notify(const std::string& method, Json params) {
  writeFrame(out_, {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
}

void Server::request(const std::string& method, Json params, ResponseHandler on_response) {
  int64_t id = next_request_id_++;
  pending_[id] = std::move(on_response);
  writeFrame(out_, {{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", params}});
}

void Server::showError(const std::string& message) {
  notify("window/showMessage", {{"type", 1}, {"message", message}});
}

}  // namespace smachac::lsp
