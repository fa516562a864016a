// The one Catch main of the workbook, compiled once per build.
//
// Protocol with the grade driver (autograder/driver):
//   --fmbd-list           print one line per test case, "name<TAB>[tag][tag]...", then exit 0
//   --fmbd-token-fd N     read a completion token (one line) from file descriptor N at start-up
//                         and print "fmbd-completion-token: <token>" as the last line of a
//                         run that returned normally from the Catch session.
// Everything else goes to Catch unchanged. This file and grading.hpp are the only places
// that know the Catch version (v2 here).
#define CATCH_CONFIG_RUNNER
#define CATCH_CONFIG_CONSOLE_WIDTH 120
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace {

std::string read_token(int fd) {
  std::string token;
  char c = 0;
  while (token.size() < 256 && ::read(fd, &c, 1) == 1 && c != '\n') token.push_back(c);
  ::close(fd);
  return token;
}

int list_tests() {
  for (const Catch::TestCase& test : Catch::getRegistryHub().getTestCaseRegistry().getAllTests()) {
    std::cout << test.name << '\t' << test.tagsAsString() << '\n';
  }
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  std::vector<char*> args{argv[0]};
  std::string token;
  bool list = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--fmbd-list") {
      list = true;
    } else if (arg == "--fmbd-token-fd" && i + 1 < argc) {
      token = read_token(std::atoi(argv[++i]));
    } else {
      args.push_back(argv[i]);
    }
  }
  if (list) return list_tests();

  const int failed = Catch::Session().run(static_cast<int>(args.size()), args.data());
  if (!token.empty()) std::cout << "\nfmbd-completion-token: " << token << std::endl;
  return failed == 0 ? 0 : 1;
}
