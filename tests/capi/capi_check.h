/* Checks shared by the C programs that test the GPU outputs of the C ABI (capi_vulkan_test.c,
 * capi_cuda_test.c): CHECK counts a failed condition in g_failures and goes on; REQUIRE_OK stops
 * the program when a call of the ABI fails, printing the library's last error. */
#ifndef OCEAN_TESTS_CAPI_CHECK_H
#define OCEAN_TESTS_CAPI_CHECK_H

#include <stdio.h>
#include <stdlib.h>

#include "ocean/ocean.h"

static int g_failures = 0;

#define CHECK(cond)                                                            \
  do {                                                                         \
    if (!(cond)) {                                                             \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
      ++g_failures;                                                            \
    }                                                                          \
  } while (0)

#define REQUIRE_OK(call)                                                                        \
  do {                                                                                          \
    ocean_status s_ = (call);                                                                   \
    if (s_ != OCEAN_OK) {                                                                       \
      fprintf(stderr, "%s:%d: %s failed: %s\n", __FILE__, __LINE__, #call, ocean_last_error()); \
      exit(1);                                                                                  \
    }                                                                                           \
  } while (0)

#endif
