// Property checks for the fuzz targets: a violated property prints what was
// expected and aborts, so libFuzzer records the input as a crash.
#ifndef CUBE_FUZZ_CHECK_H_
#define CUBE_FUZZ_CHECK_H_

#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(cond, ...)                                             \
  do {                                                                    \
    if (!(cond)) {                                                        \
      std::fprintf(stderr, "property violated at %s:%d: %s\n  ", __FILE__, \
                   __LINE__, #cond);                                      \
      std::fprintf(stderr, __VA_ARGS__);                                  \
      std::fprintf(stderr, "\n");                                         \
      std::abort();                                                       \
    }                                                                     \
  } while (0)

#endif  // CUBE_FUZZ_CHECK_H_
