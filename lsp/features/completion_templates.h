// The templates a script can name for the server's target (-I directories first, then the
// target's built-in sets, as the compiler finds them), and what their meta blocks tell
// completion: a one-line summary, the kind of template (`type`: Base, State, Container...;
// `None` for helpers that scripts do not name), the variables and the outcomes. A template
// without a meta block (a user's) is known by its name only. The search path and the
// environment are backends/meta/template_help.h's, as `smachac help` and hover use them.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "backends/meta/template_help.h"
#include "backends/tmpl/environment.h"

namespace smachac::lsp {

struct TemplateVariableInfo {
  std::string name;
  std::string description;  ///< on one line
  std::string type;         ///< as the meta block writes it: "list of str", "float or str"
  bool required = false;
  bool alternative = false;  ///< one of a choice of variables, one of which is required
};

struct TemplateInfo {
  std::string name;
  std::string summary;      ///< the first sentence of the description, on one line
  std::string description;  ///< the whole description, on one line
  std::string type;         ///< the meta block's `type`; empty without a meta block
  std::vector<TemplateVariableInfo> variables;
  std::vector<std::string> outcomes;

  /// Whether scripts name it: it has no meta block, or its type is not `None` (a helper).
  bool forScripts() const { return type != "None"; }
  bool isBase() const { return type == "Base"; }
};

class TemplateLibrary {
 public:
  /// `target`: smach, cpp or flexbe (another target reads smach's templates).
  TemplateLibrary(const std::string& target, const std::vector<std::string>& template_dirs);
  ~TemplateLibrary();

  /// Every template name on the path, sorted.
  std::vector<std::string> names() const;
  /// What the template `name` declares; nullopt when the target has no such template.
  std::optional<TemplateInfo> find(std::string_view name);

 private:
  generator::TemplatePath path_;
  generator::ValueConverter converter_;
  std::unique_ptr<tmpl::Environment> env_;
};

}  // namespace smachac::lsp
