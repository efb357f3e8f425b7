/* The C ABI's CUDA device pointers (ocean_simulator_cuda_field), in C99 against ocean.h and the
 * CUDA runtime's C API only: a simulator on the cuda backend is stepped twice (step, then kick +
 * wait); every field of every cascade (the packed map at every mip level) is copied from the
 * device pointer to the host with cudaMemcpy and must equal, byte for byte, the field the library
 * read back (ocean_simulator_field): the readback copies those very bytes, so any other answer is
 * a wrong address, layout or frame. The velocity (not computed on CUDA) is refused. Without a
 * CUDA device (no driver, no GPU) the library answers OCEAN_UNSUPPORTED "no CUDA device: ...":
 * the test then checks that a CPU simulator's request is refused naming its backend, and exits
 * 77 (skipped). */
#include <cuda_runtime_api.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_check.h"
#include "ocean/ocean.h"


/* Every field of every cascade through the device pointer against the host readback; returns
 * the bytes compared. */
static size_t compare_frame(const ocean_simulator* sim, size_t cascades, int resolution) {
  static const ocean_field fields[] = {OCEAN_FIELD_DISPLACEMENT, OCEAN_FIELD_DISPLACEMENT_HALF,
                                       OCEAN_FIELD_NORMAL,       OCEAN_FIELD_JACOBIAN,
                                       OCEAN_FIELD_FOAM,         OCEAN_FIELD_PACKED};
  size_t c, f, compared = 0;
  int levels = 0;
  while ((1 << levels) < resolution) ++levels;
  for (c = 0; c < cascades; ++c) {
    for (f = 0; f < sizeof fields / sizeof fields[0]; ++f) {
      const int32_t top = fields[f] == OCEAN_FIELD_PACKED ? levels : 0;
      int32_t level;
      for (level = 0; level <= top; ++level) {
        ocean_field_view host, device;
        int32_t ordinal = -1;
        size_t bytes;
        void* copy;
        memset(&host, 0, sizeof host);
        memset(&device, 0, sizeof device);
        host.struct_size = device.struct_size = sizeof host;
        REQUIRE_OK(ocean_simulator_field(sim, c, fields[f], level, &host));
        REQUIRE_OK(ocean_simulator_cuda_field(sim, c, fields[f], level, &device, &ordinal));
        CHECK(ordinal >= 0);
        CHECK(device.width == host.width && device.height == host.height &&
              device.channels == host.channels && device.element == host.element &&
              device.row_stride_bytes == host.row_stride_bytes &&
              device.patch_size_m == host.patch_size_m);
        bytes = host.row_stride_bytes * (size_t)host.height;
        copy = malloc(bytes);
        CHECK(copy != NULL);
        if (copy == NULL) continue;
        CHECK(cudaSetDevice(ordinal) == cudaSuccess);
        CHECK(cudaMemcpy(copy, device.data, bytes, cudaMemcpyDeviceToHost) == cudaSuccess);
        if (memcmp(copy, host.data, bytes) != 0) {
          fprintf(stderr, "cascade %zu field %d level %d: device bytes differ from the readback\n",
                  c, (int)fields[f], (int)level);
          ++g_failures;
        }
        compared += bytes;
        free(copy);
      }
    }
  }
  return compared;
}

int main(void) {
  ocean_config* config = NULL;
  ocean_simulator *sim = NULL, *cpu = NULL;
  ocean_field_view view;
  ocean_status status;
  size_t cascades = 0, compared;
  REQUIRE_OK(ocean_config_create(&config));
  REQUIRE_OK(ocean_config_merge_preset(config, "moderate"));
  REQUIRE_OK(ocean_config_set(config, "resolution=64"));
  memset(&view, 0, sizeof view);
  view.struct_size = sizeof view;

  status = ocean_simulator_create(config, "cuda", &sim);
  if (status == OCEAN_UNSUPPORTED) {
    char why[512];
    snprintf(why, sizeof why, "%s", ocean_last_error());
    REQUIRE_OK(ocean_simulator_create(config, "cpu", &cpu));
    REQUIRE_OK(ocean_simulator_step(cpu, 1.0));
    status = ocean_simulator_cuda_field(cpu, 0, OCEAN_FIELD_DISPLACEMENT, 0, &view, NULL);
    CHECK(status == OCEAN_UNSUPPORTED);
    CHECK(strstr(ocean_last_error(), "runs on the 'cpu' backend") != NULL);
    CHECK(view.data == NULL);
    ocean_simulator_destroy(cpu);
    ocean_config_destroy(config);
    if (g_failures != 0) return 1;
    printf("skipped: %s\n", why);
    return 77;
  }
  REQUIRE_OK(status);
  REQUIRE_OK(ocean_simulator_cascade_count(sim, &cascades));
  REQUIRE_OK(ocean_simulator_step(sim, 1.7));
  compared = compare_frame(sim, cascades, 64);
  REQUIRE_OK(ocean_simulator_kick(sim, 2.3));
  REQUIRE_OK(ocean_simulator_wait(sim));
  compared += compare_frame(sim, cascades, 64);
  status = ocean_simulator_cuda_field(sim, 0, OCEAN_FIELD_VELOCITY, 0, &view, NULL);
  CHECK(status == OCEAN_UNSUPPORTED);
  status = ocean_simulator_cuda_field(sim, cascades, OCEAN_FIELD_DISPLACEMENT, 0, &view, NULL);
  CHECK(status == OCEAN_INVALID_ARGUMENT);
  CHECK(view.data == NULL);
  ocean_simulator_destroy(sim);
  ocean_config_destroy(config);
  printf("%zu bytes over %zu cascades and two frames equal the readback\n", compared, cascades);
  if (g_failures != 0) {
    fprintf(stderr, "%d check(s) failed\n", g_failures);
    return 1;
  }
  printf("ok\n");
  return 0;
}
