// The SMACHA-shaped template workload (see tmpl_workload.h).
#include "bench/tmpl_workload.h"

#include <algorithm>
#include <string_view>

namespace smachac::bench {
namespace {

using tmpl::Value;

Value strings(std::initializer_list<std::string> items) {
  std::vector<Value> out;
  for (const std::string& s : items) out.push_back(Value::string(s));
  return Value::newList(std::move(out));
}

Value dictOf(std::initializer_list<std::pair<std::string, Value>> items) {
  Value d = Value::newDict();
  for (const auto& [k, v] : items) d.dict().setString(k, v);
  return d;
}

std::string strip(const std::string& s) {
  size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  size_t e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

}  // namespace

Value stateContext(int i, int count, const Value& definedHeaders) {
  std::string n = std::to_string(i);
  std::string next = i + 1 < count ? "STATE_" + std::to_string(i + 1) : "done";
  return dictOf({
      {"name", Value::string("STATE_" + n)},
      {"class_name", Value::string("WorkState")},
      {"parent_type", Value::string("StateMachine")},
      {"parent_sm_name", Value::string("sm_top")},
      {"outcomes", strings({"succeeded", "aborted"})},
      {"input_keys", strings({"in_a", "in_b"})},
      {"output_keys", strings({"out_x"})},
      {"transitions",
       dictOf({{"succeeded", Value::string(next)}, {"aborted", Value::string("failed")}})},
      {"remapping",
       dictOf({{"in_a", Value::string("data_" + n)}, {"in_b", Value::string("shared")}})},
      {"userdata", dictOf({{"x_" + n, Value::real(i * 0.5)},
                           {"label", Value::string("state " + n)},
                           {"target", Value::string("pkg.msg.Obj")}})},
      {"duration", Value::real((i % 5) * 0.1)},
      {"defined_headers", definedHeaders},
  });
}

namespace {

// The code of each block, in the order of `blocks` (SMACHA's per-block buffers).
using Buffers = std::vector<std::vector<std::string>>;

// The non-empty codes of block `name`, each followed by a line break, stripped.
std::string joinedCode(const std::vector<std::string>& blocks, const Buffers& buffers,
                       std::string_view name) {
  auto it = std::find(blocks.begin(), blocks.end(), name);
  if (it == blocks.end()) return "";
  std::string joined;
  for (const std::string& code : buffers[static_cast<size_t>(it - blocks.begin())]) {
    joined += code;
    joined += '\n';
  }
  return strip(joined);
}

}  // namespace

size_t runSmachaWorkload(tmpl::Environment& env, int count) {
  const std::string state = "WorkState.tpl.py";
  std::vector<std::string> blocks;
  for (const std::string& b : env.listBlocks(state)) {
    if (b != "meta") blocks.push_back(b);
  }
  Value definedHeaders = Value::newList();
  Buffers buffers(blocks.size());
  for (int i = 0; i < count; ++i) {
    Value ctx = stateContext(i, count, definedHeaders);
    for (size_t b = 0; b < blocks.size(); ++b) {
      std::string code = env.renderBlock(state, blocks[b], ctx);
      if (!code.empty()) buffers[b].push_back(std::move(code));
    }
  }
  Value base = dictOf({{"name", Value::string("top")}, {"outcomes", strings({"done", "failed"})}});
  for (const char* name : {"base_header", "imports", "defs", "class_defs", "cb_defs", "main_def",
                           "body", "footer", "execute", "base_footer"}) {
    base.dict().setString(name, Value::string(joinedCode(blocks, buffers, name)));
  }
  std::string header = joinedCode(blocks, buffers, "header");
  base.dict().setString("header", dictOf({{"sm_top", Value::string(header)}}));
  return env.render("Base.tpl.py", base, tmpl::RenderOptions{{"meta"}}).size();
}

}  // namespace smachac::bench
