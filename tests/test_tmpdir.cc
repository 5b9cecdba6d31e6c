// Copyright contactlaws authors.
//
// Linked into every test program: the tests' files (::testing::TempDir(),
// which reads TEST_TMPDIR) go to this build tree's test-tmp/, not to a /tmp
// shared by every build and checkout on the machine, where two suites run at
// once overwrote each other's fixed names. A TEST_TMPDIR already set wins.

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace {

const bool kTestTmpDirSet = [] {
  std::error_code ignored;
  std::filesystem::create_directories(CONTACTLAWS_TEST_TMPDIR, ignored);
  setenv("TEST_TMPDIR", CONTACTLAWS_TEST_TMPDIR "/", /*overwrite=*/0);
  return true;
}();

}  // namespace
