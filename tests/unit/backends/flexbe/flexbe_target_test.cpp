// The FlexBE target's text handling: [MANUAL_*] sections kept byte for byte, file split.
#include <doctest/doctest.h>

#include "backends/flexbe/flexbe_target.h"
#include "backends/flexbe/manual_sections.h"

using smachac::backends::flexbe::keepManualSections;
using smachac::backends::flexbe::splitFiles;

TEST_CASE("manual sections of the existing file replace the generated ones") {
  std::string generated =
      "a\n# [MANUAL_IMPORT]\n\n# [/MANUAL_IMPORT]\n    # [MANUAL_INIT]\n\n    # [/MANUAL_INIT]\n";
  std::string existing =
      "old\n# [MANUAL_IMPORT]\nimport os\r\n\t \n# [/MANUAL_IMPORT]\n"
      "    # [MANUAL_INIT]\n        self.x = 1  \n    # [/MANUAL_INIT]\nold\n";
  std::optional<std::string> merged = keepManualSections(generated, existing);
  REQUIRE(merged);
  CHECK(*merged ==
        "a\n# [MANUAL_IMPORT]\nimport os\r\n\t \n# [/MANUAL_IMPORT]\n"
        "    # [MANUAL_INIT]\n        self.x = 1  \n    # [/MANUAL_INIT]\n");
}

TEST_CASE("sections absent from the existing file keep the generated text") {
  std::string generated = "# [MANUAL_FUNC]\n\n# [/MANUAL_FUNC]\n";
  CHECK(keepManualSections(generated, "nothing here\n") == generated);
  CHECK(keepManualSections(generated, "# [MANUAL_FUNC]\n# [/MANUAL_FUNC]\n") ==
        generated.substr(0, 16) + "# [/MANUAL_FUNC]\n");
}

TEST_CASE("a tag inside a line (a string value) is no tag") {
  std::string generated =
      "x = '# [MANUAL_CREATE]'\ngenerated 2\n  # [MANUAL_CREATE]\n\n  # [/MANUAL_CREATE]\n";
  std::string existing =
      "x = '# [MANUAL_CREATE]'\ngenerated 1\n  # [MANUAL_CREATE]\nkept\n  # [/MANUAL_CREATE]\n";
  CHECK(keepManualSections(generated, existing) ==
        "x = '# [MANUAL_CREATE]'\ngenerated 2\n  # [MANUAL_CREATE]\nkept\n  # [/MANUAL_CREATE]\n");
  CHECK(keepManualSections(generated, "y = '# [/MANUAL_CREATE]'\n") == generated);
}

TEST_CASE("an unclosed or reversed tag is an error") {
  std::string generated = "# [MANUAL_INIT]\n\n# [/MANUAL_INIT]\n";
  CHECK_FALSE(keepManualSections(generated, "# [MANUAL_INIT]\nx\n"));
  CHECK_FALSE(keepManualSections(generated, "# [/MANUAL_INIT]\n# [MANUAL_INIT]\n"));
  CHECK_FALSE(keepManualSections(generated, "x\n# [/MANUAL_CREATE]\n"));
}

TEST_CASE("the base template's output splits on #@smachac-file lines") {
  auto files = splitFiles("#@smachac-file a_sm.py\nline 1\n\n#@smachac-file a.xml\n<x/>");
  REQUIRE(files.size() == 2);
  CHECK(files[0].name == "a_sm.py");
  CHECK(files[0].content == "line 1\n");
  CHECK(files[1].name == "a.xml");
  CHECK(files[1].content == "<x/>\n");
}
