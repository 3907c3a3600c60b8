// The language server: reads JSON-RPC messages from `in` on a reader thread, answers them in
// order on the calling thread, and writes to `out`. Lifecycle as LSP 3.17 says: requests
// before `initialize` get ServerNotInitialized, requests after `shutdown` InvalidRequest,
// `exit` ends the loop (exit code 0 after shutdown, 1 without). Diagnostics are published
// when no message is waiting, so a burst of changes is analysed once.
#pragma once

#include <functional>
#include <iosfwd>
#include <map>
#include <string>

#include "lsp/json_rpc.h"
#include "lsp/message_queue.h"
#include "lsp/workspace.h"

namespace smachac::lsp {

class Server {
 public:
  Server(std::istream& in, std::ostream& out, Settings settings);

  /// Serves until `exit` or the end of input; the process exit code.
  int run();

 private:
  enum class Phase { Uninitialized, Running, ShutDown };
  using ResponseHandler = std::function<void(const Json& response)>;

  void readMessages();
  void handle(const Json& message);
  void handleRequest(const Json& id, const std::string& method, const Json& params);
  void handleNotification(const std::string& method, const Json& params);
  void handleResponse(const Json& message);
  Json answer(const std::string& method, const Json& params);
  void initialized();
  void requestConfiguration();
  void applySettings(const Json& json);
  void publishStale();

  void reply(const Json& id, Json result);
  void replyError(const Json& id, int code, const std::string& message);
  void notify(const std::string& method, Json params);
  void request(const std::string& method, Json params, ResponseHandler on_response);
  void showError(const std::string& message);

  std::istream& in_;
  std::ostream& out_;
  MessageQueue queue_;
  Workspace workspace_;
  Phase phase_ = Phase::Uninitialized;
  bool exited_ = false;
  bool client_has_configuration_ = false;
  int64_t next_request_id_ = 1;
  std::map<int64_t, ResponseHandler> pending_;  ///< our requests to the client, by id
};

}  // namespace smachac::lsp
