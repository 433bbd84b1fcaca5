# LENSLAB_SANITIZE builds every target (libraries, binaries, tests) with the compiler's sanitizers
# (gcc's or clang's; scripts/test-sanitize builds with clang, which compiles them faster):
#   address   AddressSanitizer + LeakSanitizer + UndefinedBehaviorSanitizer (./test --sanitize)
#   thread    ThreadSanitizer (./test --sanitize-thread: the threaded tests)
# Empty (the default) builds without them. The sanitizer runs set their options and suppression
# files (scripts/sanitizers/) in the environment; see scripts/test-sanitize.
set(LENSLAB_SANITIZE "" CACHE STRING "Sanitizer build: empty, 'address' (ASan+UBSan) or 'thread' (TSan)")
set_property(CACHE LENSLAB_SANITIZE PROPERTY STRINGS "" address thread)

if(LENSLAB_SANITIZE STREQUAL "address")
  # -fno-sanitize-recover: undefined behaviour stops the test (non-zero exit), rather than
  # printing a line that a passing test would hide.
  # Without UBSan's object-size and pointer-overflow checks: the renderer's tests ran about 1.8
  # times faster without them (ApertureRender.BokehShows...: 26.1-26.3 s with, 14.0-15.1 s
  # without; clang 14, alternated in one run; docs/testing.md has the other checks' figures).
  # ASan checks every load and store against its shadow memory, which finds the out-of-object
  # accesses object-size looks for; pointer-overflow looks for pointer arithmetic that wraps
  # around the address space, and lenslab's is indexing into containers that ASan bounds.
  set(lenslab_sanitizer_flags -fsanitize=address,undefined
      -fno-sanitize=object-size,pointer-overflow -fno-sanitize-recover=undefined)
  # Tests that bound the viewer's memory with `ulimit -v` use ASan's own limits instead: ASan
  # reserves terabytes of address space for its shadow memory, which `ulimit -v` forbids.
  add_compile_definitions(LENSLAB_ADDRESS_SANITIZER=1)
elseif(LENSLAB_SANITIZE STREQUAL "thread")
  set(lenslab_sanitizer_flags -fsanitize=thread)
  add_compile_definitions(LENSLAB_THREAD_SANITIZER=1)
elseif(NOT LENSLAB_SANITIZE STREQUAL "")
  message(FATAL_ERROR "LENSLAB_SANITIZE must be empty, 'address' or 'thread', not '${LENSLAB_SANITIZE}'")
endif()

if(lenslab_sanitizer_flags)
  # Frame pointers keep the sanitizers' stack traces whole at -O2.
  add_compile_options(${lenslab_sanitizer_flags} -fno-omit-frame-pointer)
  add_link_options(${lenslab_sanitizer_flags})
endif()
