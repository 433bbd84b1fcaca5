# lenslab_test_program(TARGET): what every GoogleTest program shares, for a build that costs less.
#
# - The test code itself is compiled at -O1 in every build type: the numbers it checks are
#   computed by the libraries, which keep their own -O3 (Release) or -O2 (sanitizer builds).
#   GoogleTest's assertion macros expand into a great deal of code that -O2/-O3 and, in the
#   sanitizer builds, the instrumentation pass spend most of their time on: renderer_test.cpp
#   took 13.2 s of CPU at -O3 and 9.1 s at -O1 in Release, 33.6 s at -O2 and 21.6 s at -O1 with
#   ASan + UBSan (2026-11-27, gcc 12). -O1 still inlines and keeps the brute-force integrals
#   some tests compute on their own within a small factor of -O3.
# - A precompiled header of GoogleTest, nlohmann/json and the standard headers the tests use
#   most, parsed once per program instead of once per file (renderer_test.cpp at -O3: 13.2 s
#   -> 8.8 s).
# - Unity batches of eight files (with LENSLAB_UNITY_BUILD, as the libraries): with the
#   precompiled header, most of a small test file's compile was its fixed cost (loading the
#   header, instantiating GoogleTest's and the standard library's templates, ASan's module
#   set-up): 3 to 5 s of CPU under ASan for a file whose own code takes one. Names in a test
#   file's anonymous namespace must not clash with another file's of the same program, and a
#   test inside namespace lenslab::X writes GoogleTest's namespace as ::testing (lenslab::testing
#   is the tests' support).
function(lenslab_test_program target)
  # At -O1, gcc 12 warns falsely inside libstdc++'s inlined std::string and std::regex code
  # (-Warray-bounds, -Wrestrict and -Wstringop-overflow/-overread on string concatenation, such
  # as "writing 23 bytes into a region of size 16", the inline buffer of a string that is not
  # short; -Wmaybe-uninitialized in regex's automaton; 73 such warnings in a cold build, none
  # pointing at a line of the tests): off for the test code only.
  target_compile_options(${target} PRIVATE -O1)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${LENSLAB_UNITY_BUILD}
                                             UNITY_BUILD_BATCH_SIZE 8)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-array-bounds -Wno-restrict
                                             -Wno-maybe-uninitialized -Wno-stringop-overflow
                                             -Wno-stringop-overread)
  endif()
  target_precompile_headers(${target} PRIVATE
    <gtest/gtest.h>
    <nlohmann/json.hpp>
    <algorithm> <chrono> <cmath> <cstdint> <cstdio> <filesystem> <fstream> <functional>
    <limits> <map> <memory> <numbers> <optional> <random> <regex> <set> <sstream> <string>
    <thread> <vector>)
  # A test program runs outside the trees the resource lookup knows (common/resource_directories.h):
  # tests/support/bundled_glass.h points the glass catalogue at the checkout's copy.
  target_compile_definitions(${target} PRIVATE
    LENSLAB_BUNDLED_GLASS_DIR="${PROJECT_SOURCE_DIR}/data/glass")
endfunction()
