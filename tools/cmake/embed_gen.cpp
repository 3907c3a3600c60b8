// Build tool of embed_files.cmake: writes the C++ source of an EmbeddedFile table
// (ir/support/embedded_file.h), each file's path relative to BASE_DIR and its bytes, and with
// --tokens also the token stream the template engine's lexer makes of each (packed as
// backends/tmpl/lexer/token_table.h says), so that a compile does not lex the built-in
// templates again, and with --images each one's parsed and analysed form
// (backends/tmpl/image/image_format.h), compiled with its set's filters (target_extensions.h),
// which a compile loads instead of compiling it. Rules: the bytes are written exactly (octal
// escapes for everything but printable ASCII); a file that does not lex fails the build (a
// compile would reject it); one that does not compile gets no image (a compile reports its
// error as before); the output is only replaced when it changes.
// Usage: smachac_embed_gen OUT NAMESPACE FUNCTION BASE_DIR [--tokens] [--images] FILE...
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "backends/tmpl/environment.h"
#include "backends/tmpl/image/image_writer.h"
#include "backends/tmpl/lexer/lexer.h"
#include "backends/tmpl/lexer/token_table.h"
#include "cpp_literal.h"
#include "target_extensions.h"

namespace {

using smachac::build::cppStringLiteral;

namespace fs = std::filesystem;

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw std::runtime_error("cannot read " + path);
  return text.str();
}

/// The lexer's tokens of a template's normalised text, as the engine stores them.
std::string tokenArray(const std::string& name, const std::string& text, const std::string& path) {
  std::string source = smachac::tmpl::normalizeSource(text);
  std::vector<uint32_t> words;
  try {
    words = smachac::tmpl::packTokens(smachac::tmpl::tokenize(source));
  } catch (const smachac::tmpl::SyntaxFault& fault) {
    throw std::runtime_error(path + ": does not lex at byte " + std::to_string(fault.pos) + ": " +
                             fault.message);
  }
  std::string out = "constexpr uint32_t " + name + "[] = {";
  for (size_t i = 0; i < words.size(); ++i) {
    out += (i % 12 == 0 ? "\n    " : " ") + std::to_string(words[i]) + "u,";
  }
  return out + "\n};\n";
}

struct Options {
  std::string out, ns, function, base;
  bool tokens = false;
  bool images = false;
  std::vector<std::string> files;
};

std::string relativePath(const Options& o, const std::string& file) {
  return fs::path(file).lexically_relative(o.base).generic_string();
}

/// The image of the template at `path` ("smach/Utils.tpl.py") in `files`, compiled as a
/// compile compiles it; empty if it does not compile.
std::vector<uint8_t> templateImage(const std::string& path,
                                   std::span<const smachac::EmbeddedFile> files) {
  size_t slash = path.find('/');
  if (slash == std::string::npos) return {};
  std::string set = path.substr(0, slash + 1);
  smachac::tmpl::Environment env({}, {set}, files);
  smachac::generator::ValueConverter converter;
  smachac::build::registerSetExtensions(env, set, converter);
  try {
    return smachac::tmpl::writeTemplateImage(env.compiled(path.substr(slash + 1)));
  } catch (const std::exception&) {
    return {};
  }
}

std::string imageArray(const std::string& name, const std::vector<uint8_t>& bytes) {
  std::string out = "constexpr uint8_t " + name + "[] = {";
  for (size_t i = 0; i < bytes.size(); ++i) {
    out += (i % 20 == 0 ? "\n    " : " ") + std::to_string(bytes[i]) + ",";
  }
  return out + "\n};\n";
}

/// What each file holds as a template image (an empty one for none).
std::vector<std::vector<uint8_t>> templateImages(const Options& o,
                                                 const std::vector<std::string>& texts) {
  std::vector<std::string> paths;
  for (const std::string& file : o.files) paths.push_back(relativePath(o, file));
  std::vector<smachac::EmbeddedFile> files;
  for (size_t i = 0; i < paths.size(); ++i) files.push_back({paths[i], texts[i]});
  std::vector<std::vector<uint8_t>> images;
  for (const std::string& path : paths)
    images.push_back(o.images ? templateImage(path, files) : std::vector<uint8_t>());
  return images;
}

std::string tableSource(const Options& o) {
  std::vector<std::string> texts;
  for (const std::string& file : o.files) texts.push_back(readFile(file));
  std::vector<std::vector<uint8_t>> images = templateImages(o, texts);
  std::string data;
  std::string table;
  for (size_t i = 0; i < o.files.size(); ++i) {
    const std::string& text = texts[i];
    std::string id = std::to_string(i);
    data += "constexpr char kFile" + id + "[] =\n    " + cppStringLiteral(text, true) + ";\n";
    std::string tokens = images[i].empty() ? "" : ", {}";  // the tokens, then the image
    if (o.tokens) {
      data += tokenArray("kTokens" + id, text, o.files[i]);
      tokens = ", kTokens" + id;
    }
    if (!images[i].empty()) {
      data += imageArray("kImage" + id, images[i]);
      tokens += ", kImage" + id;
    }
    table += "    {" + cppStringLiteral(relativePath(o, o.files[i]), true) +
             ", std::string_view(kFile" + id + ", " + std::to_string(text.size()) + ")" + tokens +
             "},\n";
  }
  return "// Generated by tools/cmake/embed_gen.cpp. Do not edit.\n#include <cstdint>\n"
         "#include <span>\n\n#include \"ir/support/embedded_file.h\"\n\nnamespace " +
         o.ns + " {\nnamespace {\n\n" + data + "\nconstexpr smachac::EmbeddedFile kFiles[] = {\n" +
         table +
         "    {\"\", std::string_view()},\n};\n\n}  // namespace\n\n"
         "std::span<const smachac::EmbeddedFile> " +
         o.function +
         "() {\n  return std::span<const smachac::EmbeddedFile>(kFiles, std::size(kFiles) - 1);\n"
         "}\n\n}  // namespace " +
         o.ns + "\n";
}

void writeIfChanged(const std::string& path, const std::string& text) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream old;
  if (in) old << in.rdbuf();
  if (in && old.str() == text) return;
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::cerr << "usage: smachac_embed_gen OUT NAMESPACE FUNCTION BASE_DIR [--tokens] [--images] "
                 "FILE...\n";
    return 2;
  }
  Options o{argv[1], argv[2], argv[3], argv[4], false, false, {}};
  for (int i = 5; i < argc; ++i) {
    if (std::string(argv[i]) == "--tokens") {
      o.tokens = true;
    } else if (std::string(argv[i]) == "--images") {
      o.images = true;
    } else {
      o.files.emplace_back(argv[i]);
    }
  }
  try {
    writeIfChanged(o.out, tableSource(o));
  } catch (const std::exception& e) {
    std::cerr << "smachac_embed_gen: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
