// The C++ side of the differential template tests: renders every case of a directory of
// `.cases` files (format in README.md) with smachac's engine and prints one JSON object per
// operation: {"case", "op", "ok", "out"}. run_diff.py compares them with Jinja2.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "backends/tmpl/environment.h"
#include "backends/tmpl/values/value_convert.h"
#include "backends/tmpl/values/value_print.h"

namespace {

namespace fs = std::filesystem;
using smachac::tmpl::Environment;
using smachac::tmpl::RenderOptions;
using smachac::tmpl::TemplateError;
using smachac::tmpl::Value;

struct TemplateFile {
  std::string name;
  std::set<std::string> flags;
  std::vector<std::string> lines;
};

struct Case {
  std::string name;
  std::vector<TemplateFile> templates;
  std::vector<std::string> context;
  std::vector<std::string> ops;
};

std::vector<std::string> splitWords(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

std::vector<std::string> stripTail(std::vector<std::string> lines) {
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  return lines;
}

void parseFile(const fs::path& path, std::vector<Case>& cases) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string content = text.str();
  std::vector<std::string>* section = nullptr;
  bool in_case = false;
  size_t start = 0;
  while (start <= content.size()) {
    size_t end = content.find('\n', start);
    if (end == std::string::npos) end = content.size();
    std::string line = content.substr(start, end - start);
    start = end + 1;
    if (line.rfind("#### ", 0) == 0) {
      std::string name = line.substr(5);
      name.erase(name.find_last_not_of(" \t") + 1);
      cases.push_back(Case{path.stem().string() + "/" + name, {}, {}, {}});
      in_case = true;
      section = nullptr;
    } else if (!in_case) {
      continue;
    } else if (line.rfind("--- ", 0) == 0) {
      std::vector<std::string> words = splitWords(line.substr(4));
      Case& c = cases.back();
      if (words[0] == "context") {
        section = &c.context;
      } else if (words[0] == "ops") {
        section = &c.ops;
      } else {
        c.templates.push_back(TemplateFile{words[0], {words.begin() + 1, words.end()}, {}});
        section = &c.templates.back().lines;
      }
    } else if (section) {
      section->push_back(line);
    }
  }
}

std::string templateText(const TemplateFile& t) {
  std::string text;
  std::vector<std::string> lines = stripTail(t.lines);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (i > 0) text += '\n';
    text += lines[i];
  }
  if (!t.flags.count("noeol")) text += '\n';
  if (t.flags.count("crlf")) {
    std::string crlf;
    for (char ch : text) crlf += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
    text = crlf;
  }
  return text;
}

std::string join(const std::vector<std::string>& lines, const std::string& sep) {
  std::string out;
  for (size_t i = 0; i < lines.size(); ++i) out += (i ? sep : "") + lines[i];
  return out;
}

std::string runOp(Environment& env, const std::string& main, const Value& context,
                  const std::string& op) {
  std::vector<std::string> words = splitWords(op);
  RenderOptions options;
  std::vector<std::string> args;
  for (size_t i = 1; i < words.size(); ++i) {
    if (words[i].rfind("skip=", 0) == 0) {
      std::stringstream list(words[i].substr(5));
      for (std::string name; std::getline(list, name, ',');) {
        if (!name.empty()) options.skip_blocks.push_back(name);
      }
    } else if (words[i] != "error") {
      args.push_back(words[i]);
    }
  }
  const std::string& kind = words[0];
  if (kind == "render") return env.render(main, context, options);
  if (kind == "block") return env.renderBlock(main, args.at(0), context, options);
  if (kind == "blocks") return join(env.listBlocks(main), "\n");
  if (kind == "vars") {
    std::vector<std::string> lines;
    for (const auto& [name, value] : env.moduleVariables(main, context, options)) {
      lines.push_back(name + " = " + smachac::tmpl::repr(value));
    }
    return join(lines, "\n");
  }
  if (kind == "meta") return env.metaBlock(main).value_or("<none>");
  throw std::runtime_error("unknown op " + op);
}

void runCase(const Case& c) {
  static const std::vector<smachac::EmbeddedFile> kNoBuiltins;
  std::vector<std::string> ops;
  for (const std::string& op : stripTail(c.ops)) {
    if (op.find_first_not_of(" \t") != std::string::npos) ops.push_back(op);
  }
  if (ops.empty()) ops.push_back("render");
  for (const std::string& op : ops) {
    nlohmann::json record{{"case", c.name}, {"op", op}};
    try {
      Environment env({}, {}, kNoBuiltins);
      for (const TemplateFile& t : c.templates) env.addTemplate(t.name, templateText(t));
      Value context = smachac::tmpl::parseYaml(join(c.context, "\n"), "context");
      if (context.isNone()) context = Value::newDict();
      record["out"] = runOp(env, c.templates.at(0).name, context, op);
      record["ok"] = true;
    } catch (const TemplateError& e) {
      record["ok"] = false;
      record["out"] = e.what();
    }
    std::cout << record.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: tmpl_diff_runner CASES_DIR\n";
    return 2;
  }
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(argv[1])) {
    if (entry.path().extension() == ".cases") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<Case> cases;
  for (const fs::path& f : files) parseFile(f, cases);
  for (const Case& c : cases) runCase(c);
  return 0;
}
