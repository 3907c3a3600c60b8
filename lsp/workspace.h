// What the server knows: the open documents, the settings, and one analysis per open
// document, redone lazily. A document is "dirty" when its analysis is out of date: after its
// own change, after a change to a sub-script it read, after a document was opened or closed
// (a sub-script that was not found may now be), and after the settings changed. Scripts
// that are not open are analysed when they include a document that changed.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lsp/analysis.h"
#include "lsp/closed_scripts.h"
#include "lsp/documents.h"
#include "lsp/settings.h"

namespace smachac::lsp {

class Workspace {
 public:
  explicit Workspace(Settings settings) : settings_(std::move(settings)) {}

  DocumentStore& documents() { return documents_; }
  const Settings& settings() const { return settings_; }
  void setSettings(Settings settings);
  /// What the client supports: the `capabilities` of its `initialize` request.
  const Json& clientCapabilities() const { return client_capabilities_; }
  void setClientCapabilities(Json capabilities) { client_capabilities_ = std::move(capabilities); }

  void opened(const std::string& uri);
  void changed(const std::string& uri);
  void closed(const std::string& uri);
  /// Files changed on disk: every analysis may be out of date.
  void filesChanged();

  /// The up-to-date analysis of an open document, or null when it is not open.
  const Analysis* analysis(const std::string& uri);

  /// The documents whose diagnostics must be published again, the ones the user changed
  /// first, then the ones that depend on them; clears the list.
  std::vector<std::string> takeStale();
  /// Documents closed since the last call: their diagnostics must be cleared.
  std::vector<std::string> takeClosed();

  /// The workspace folders (paths), where closed scripts are looked for.
  void setRoots(std::vector<std::string> roots) { closed_scripts_.setRoots(std::move(roots)); }
  /// The analyses of the closed scripts that read a document changed since the last call
  /// (closed_scripts.h); clears the list of changes.
  std::vector<std::unique_ptr<Analysis>> takeClosedDependents();

 private:
  void markAll();
  void markDependents(const std::string& canonical_path);
  void markStale(const std::string& uri);

  Settings settings_;
  Json client_capabilities_ = Json::object();
  DocumentStore documents_;
  std::map<std::string, std::unique_ptr<Analysis>> analyses_;  ///< by URI; absent: dirty
  std::vector<std::string> stale_;  ///< to publish, in order, without repeats
  std::vector<std::string> closed_;
  std::vector<std::string> changed_files_;  ///< canonical paths, without repeats
  ClosedScripts closed_scripts_;
};

}  // namespace smachac::lsp
