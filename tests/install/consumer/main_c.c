/* A C program built against the installed C ABI (find_package(ocean), target ocean::c). */
#include <stdio.h>

#include "ocean/ocean.h"

int main(void) {
  ocean_config* config = NULL;
  ocean_simulator* sim = NULL;
  double x = 10.0, z = 20.0, h = 0.0;
  if (ocean_abi_version() != OCEAN_ABI_VERSION || ocean_config_create(&config) != OCEAN_OK ||
      ocean_config_merge_preset(config, "calm") != OCEAN_OK ||
      ocean_config_set(config, "resolution=32") != OCEAN_OK ||
      ocean_simulator_create(config, "cpu", &sim) != OCEAN_OK ||
      ocean_simulator_step(sim, 1.0) != OCEAN_OK ||
      ocean_simulator_heights(sim, &x, &z, 1, &h) != OCEAN_OK) {
    fprintf(stderr, "consumer_c: %s\n", ocean_last_error());
    return 1;
  }
  printf("ocean %s: height at (10, 20) m = %.4f m\n", ocean_version_string(), h);
  ocean_simulator_destroy(sim);
  ocean_config_destroy(config);
  return 0;
}
