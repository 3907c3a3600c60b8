// libFuzzer harness, differential: the simple YAML reader against yaml-cpp. Whenever the simple
// reader does not give up, yaml-cpp must accept the text without a diagnostic and build the
// same tree (values, kinds and every location); anything else aborts.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "ir/support/utf8.h"
#include "tests/unit/frontend/yaml_reader_diff.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  if (smachac::findInvalidUtf8(text)) return 0;  // the loader rejects these before parsing
  if (!smachac::frontend::readSimpleYaml(1, text)) return 0;  // yaml-cpp alone: nothing to compare
  smachac::test::YamlReaderComparison r = smachac::test::compareYamlReaders(text);
  if (r.reference_clean && r.simple == r.reference) return 0;
  std::fprintf(stderr, "simple reader differs from yaml-cpp%s\n--- simple\n%s--- yaml-cpp\n%s",
               r.reference_clean ? "" : " (yaml-cpp reports a diagnostic)", r.simple.c_str(),
               r.reference.c_str());
  std::abort();
}
