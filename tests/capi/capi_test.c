/* The C ABI (include/ocean/ocean.h) used from C99: the heights, normals, velocities and spectrum
 * of the C++ API's reference scenario reproduced exactly (the surface queries on a job system
 * written here, which must be called), exact identities of the field views, the layout of every
 * field, the preset round trip, every error path (a status and a one-line message), and the
 * log and allocation hooks (the reference reproduced on the host's memory, every block back).
 *
 * Usage: capi_test REFERENCE.txt TMPDIR (REFERENCE.txt from capi_reference). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ocean/ocean.h"

static int failures = 0;

#define CHECK(cond)                                                            \
  do {                                                                         \
    if (!(cond)) {                                                             \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                              \
    }                                                                          \
  } while (0)

/* A call that must succeed. */
#define OK(call)                                                                                 \
  do {                                                                                           \
    ocean_status s_ = (call);                                                                    \
    if (s_ != OCEAN_OK) {                                                                        \
      fprintf(stderr, "%s:%d: %s -> %s: %s\n", __FILE__, __LINE__, #call, ocean_status_name(s_), \
              ocean_last_error());                                                               \
      ++failures;                                                                                \
    }                                                                                            \
  } while (0)

/* A call that must fail with `expected` and a one-line message holding `fragment`. */
static void expect_error(ocean_status got, ocean_status expected, const char* fragment,
                         const char* what, int line) {
  const char* message = ocean_last_error();
  if (got != expected || strstr(message, fragment) == NULL || strchr(message, '\n') != NULL) {
    fprintf(stderr, "capi_test.c:%d: %s: got %s \"%s\", expected %s with \"%s\"\n", line, what,
            ocean_status_name(got), message, ocean_status_name(expected), fragment);
    ++failures;
  }
}
#define ERROR(call, expected, fragment) \
  expect_error((call), (expected), (fragment), #call, __LINE__)

#define MAX_POINTS 64
#define MAX_SETS 8

/* The scenario and the C++ API's results, as capi_reference wrote them. */
struct reference {
  char preset[256];
  char sets[MAX_SETS][256];
  int set_count;
  double time_s;
  double x[MAX_POINTS], z[MAX_POINTS], h[MAX_POINTS];
  size_t points;
  double omega[MAX_POINTS], s[MAX_POINTS], hs, tp;
  size_t omegas;
  /* Simulator::surface_at with the velocity output: height, normal, velocity. */
  double sx[MAX_POINTS], sz[MAX_POINTS], sh[MAX_POINTS], normal[3 * MAX_POINTS],
      velocity[3 * MAX_POINTS];
  size_t surfaces;
};

static int read_reference(const char* path, struct reference* r) {
  char line[200];
  FILE* f = fopen(path, "r");
  if (f == NULL) return 0;
  memset(r, 0, sizeof *r);
  while (fgets(line, sizeof line, f) != NULL) {
    line[strcspn(line, "\n")] = '\0';
    if (strncmp(line, "preset ", 7) == 0) {
      snprintf(r->preset, sizeof r->preset, "%s", line + 7);
    } else if (strncmp(line, "set ", 4) == 0 && r->set_count < MAX_SETS) {
      snprintf(r->sets[r->set_count++], sizeof r->sets[0], "%s", line + 4);
    } else if (sscanf(line, "time %lf", &r->time_s) == 1) {
    } else if (r->points < MAX_POINTS && sscanf(line, "height %lf %lf %lf", &r->x[r->points],
                                                &r->z[r->points], &r->h[r->points]) == 3) {
      ++r->points;
    } else if (r->omegas < MAX_POINTS &&
               sscanf(line, "spectrum jonswap %lf %lf %lf %lf", &r->hs, &r->tp,
                      &r->omega[r->omegas], &r->s[r->omegas]) == 4) {
      ++r->omegas;
    } else if (r->surfaces < MAX_POINTS) {
      const size_t i = r->surfaces;
      if (sscanf(line, "surface %lf %lf %lf %lf %lf %lf %lf %lf %lf", &r->sx[i], &r->sz[i],
                 &r->sh[i], &r->normal[3 * i], &r->normal[3 * i + 1], &r->normal[3 * i + 2],
                 &r->velocity[3 * i], &r->velocity[3 * i + 1], &r->velocity[3 * i + 2]) == 9)
        ++r->surfaces;
    }
  }
  fclose(f);
  return r->points > 0 && r->omegas > 0 && r->surfaces > 0 && r->preset[0] != '\0';
}

static ocean_config* reference_config(const struct reference* r) {
  ocean_config* config = NULL;
  int i;
  OK(ocean_config_create(&config));
  OK(ocean_config_merge_preset(config, r->preset));
  for (i = 0; i < r->set_count; ++i) OK(ocean_config_set(config, r->sets[i]));
  return config;
}

/* The C++ API's heights and spectrum, reproduced exactly through the ABI. */
static void test_reference(const struct reference* r) {
  ocean_config* config = reference_config(r);
  ocean_simulator* sim = NULL;
  double heights[MAX_POINTS], spectrum[MAX_POINTS], t = -1.0;
  uint64_t index = 99;
  size_t i;
  ocean_spectrum_params p;
  OK(ocean_simulator_create(config, "cpu", &sim));
  OK(ocean_simulator_step(sim, r->time_s));
  OK(ocean_simulator_heights(sim, r->x, r->z, r->points, heights));
  for (i = 0; i < r->points; ++i) CHECK(heights[i] == r->h[i]);
  OK(ocean_simulator_frame_time(sim, &t, &index));
  CHECK(t == r->time_s && index == 1);
  /* A kicked frame published by wait is the stepped one; the old frame stays readable meanwhile. */
  OK(ocean_simulator_step(sim, 0.0));
  OK(ocean_simulator_kick(sim, r->time_s));
  OK(ocean_simulator_frame_time(sim, &t, NULL));
  CHECK(t == 0.0);
  OK(ocean_simulator_wait(sim));
  OK(ocean_simulator_heights(sim, r->x, r->z, r->points, heights));
  for (i = 0; i < r->points; ++i) CHECK(heights[i] == r->h[i]);
  /* Frames are counted one by one, whichever of the two buffers holds them, stepped or kicked. */
  OK(ocean_simulator_frame_time(sim, NULL, &index));
  CHECK(index == 3);
  for (i = 4; i <= 7; ++i) {
    if (i % 2 == 0) {
      OK(ocean_simulator_step(sim, r->time_s + (double)i));
    } else {
      OK(ocean_simulator_kick(sim, r->time_s + (double)i));
      OK(ocean_simulator_wait(sim));
    }
    OK(ocean_simulator_frame_time(sim, NULL, &index));
    CHECK(index == i);
  }
  ocean_simulator_destroy(sim);
  ocean_config_destroy(config);

  ocean_spectrum_params_init(&p);
  p.hs_m = r->hs;
  p.tp_s = r->tp;
  OK(ocean_spectrum_evaluate(&p, r->omega, r->omegas, spectrum));
  for (i = 0; i < r->omegas; ++i) CHECK(spectrum[i] == r->s[i]);
}

/* Exact identities of the field views: with choppiness 0 the surface is the sum of the cascades'
 * bilinear height maps, so at the origin (texel 0 of every cascade) the height is the sum of the
 * cascades' first texels, and everywhere it is bounded by the sum of their largest |h|. */
static void test_fields(void) {
  ocean_config* config = NULL;
  ocean_simulator* sim = NULL;
  ocean_field_view v;
  size_t cascades = 0, c, i;
  double at_origin = 0.0, bound = 0.0, x[100], z[100], h[100], zero = 0.0, h0 = 0.0;
  OK(ocean_config_create(&config));
  OK(ocean_config_set(config, "resolution=32"));
  OK(ocean_config_set(config, "choppiness=0"));
  OK(ocean_simulator_create(config, "cpu", &sim));
  OK(ocean_simulator_step(sim, 3.5));
  OK(ocean_simulator_cascade_count(sim, &cascades));
  CHECK(cascades == 3);
  for (c = 0; c < cascades; ++c) {
    const float* d;
    float largest = 0.0f;
    memset(&v, 0, sizeof v);
    v.struct_size = sizeof v;
    OK(ocean_simulator_field(sim, c, OCEAN_FIELD_DISPLACEMENT, 0, &v));
    CHECK(v.width == 32 && v.height == 32 && v.channels == 3);
    CHECK(v.element == OCEAN_ELEMENT_FLOAT32 && v.row_stride_bytes == 32 * 3 * 4);
    CHECK(v.patch_size_m > 0.0);
    d = (const float*)v.data;
    at_origin += (double)d[1];
    for (i = 0; i < 32 * 32; ++i) {
      /* No horizontal displacement but the FFT's rounding (~1e-9 m), far below the query's
       * 1e-6 m tolerance: the query lands on its point without iterating. */
      CHECK(fabsf(d[3 * i]) < 1e-7f && fabsf(d[3 * i + 2]) < 1e-7f);
      if (fabsf(d[3 * i + 1]) > largest) largest = fabsf(d[3 * i + 1]);
    }
    bound += (double)largest;
    OK(ocean_simulator_field(sim, c, OCEAN_FIELD_DISPLACEMENT_HALF, 0, &v));
    CHECK(v.channels == 4 && v.element == OCEAN_ELEMENT_FLOAT16 && v.row_stride_bytes == 32 * 8);
    OK(ocean_simulator_field(sim, c, OCEAN_FIELD_NORMAL, 0, &v));
    CHECK(v.channels == 3 && v.element == OCEAN_ELEMENT_FLOAT32);
    OK(ocean_simulator_field(sim, c, OCEAN_FIELD_JACOBIAN, 0, &v));
    CHECK(v.channels == 1 && v.row_stride_bytes == 32 * 4);
    CHECK(fabsf(((const float*)v.data)[0] - 1.0f) < 1e-5f); /* J = 1: no horizontal motion */
    OK(ocean_simulator_field(sim, c, OCEAN_FIELD_FOAM, 0, &v));
    CHECK(v.channels == 1 && v.element == OCEAN_ELEMENT_FLOAT32);
    OK(ocean_simulator_field(sim, c, OCEAN_FIELD_PACKED, 5, &v));
    CHECK(v.width == 1 && v.height == 1 && v.channels == 4 && v.element == OCEAN_ELEMENT_UINT8);
    OK(ocean_simulator_field(sim, c, OCEAN_FIELD_PACKED, 0, &v));
    CHECK(v.width == 32 && v.row_stride_bytes == 32 * 4);
  }
  OK(ocean_simulator_heights(sim, &zero, &zero, 1, &h0));
  CHECK(h0 == at_origin);
  for (i = 0; i < 100; ++i) {
    x[i] = -500.0 + 10.37 * (double)i;
    z[i] = 250.0 - 7.13 * (double)i;
  }
  OK(ocean_simulator_heights(sim, x, z, 100, h));
  for (i = 0; i < 100; ++i) CHECK(fabs(h[i]) <= bound);
  CHECK(bound > 0.0);
  ocean_simulator_destroy(sim);
  ocean_config_destroy(config);
}

/* A configuration saved and merged back is the same configuration; to_json is snprintf-like. */
static void test_presets(const char* tmpdir) {
  ocean_config *a = NULL, *b = NULL;
  char path[512], small[8], *text_a, *text_b;
  size_t length = 0, length_b = 0, i;
  CHECK(ocean_builtin_preset_count() == 3);
  CHECK(strcmp(ocean_builtin_preset_name(0), "calm") == 0);
  CHECK(ocean_builtin_preset_name(3) == NULL);
  for (i = 0; i < ocean_builtin_preset_count(); ++i) {
    OK(ocean_config_create(&a));
    OK(ocean_config_merge_preset(a, ocean_builtin_preset_name(i)));
    ocean_config_destroy(a);
  }
  OK(ocean_config_create(&a));
  OK(ocean_config_merge_preset(a, "storm"));
  OK(ocean_config_set(a, "sea.wind_sea.fetch_m=5e4"));
  OK(ocean_config_to_json(a, NULL, 0, &length));
  CHECK(length > 100);
  OK(ocean_config_to_json(a, small, sizeof small, &length_b));
  CHECK(length_b == length && strlen(small) == sizeof small - 1 && small[0] == '{');
  text_a = (char*)malloc(length + 1);
  text_b = (char*)malloc(length + 1);
  OK(ocean_config_to_json(a, text_a, length + 1, &length));
  CHECK(strstr(text_a, "\"fetch_m\": 50000") != NULL);
  snprintf(path, sizeof path, "%s/capi_preset.json", tmpdir);
  OK(ocean_config_save(a, path));
  OK(ocean_config_create(&b));
  OK(ocean_config_merge_preset(b, path));
  OK(ocean_config_to_json(b, text_b, length + 1, &length_b));
  CHECK(length_b == length && strcmp(text_a, text_b) == 0);
  free(text_a);
  free(text_b);
  ocean_config_destroy(a);
  ocean_config_destroy(b);
}

/* An engine's job system: runs every loop on the calling thread, chunk by chunk, and the
 * background job inline; counts what the simulator asks of it. */
struct counting_jobs {
  unsigned long loops, ranges, indices, starts, waits;
  void* last_handle;
};

static void jobs_parallel_for(void* user_data, size_t count, size_t grain, ocean_job_range_fn body,
                              void* job_data) {
  struct counting_jobs* jobs = (struct counting_jobs*)user_data;
  size_t begin;
  ++jobs->loops;
  for (begin = 0; begin < count; begin += grain) {
    const size_t end = count - begin > grain ? begin + grain : count;
    ++jobs->ranges;
    jobs->indices += (unsigned long)(end - begin);
    body(job_data, begin, end);
  }
}

static void* jobs_start(void* user_data, ocean_job_fn job, void* job_data) {
  struct counting_jobs* jobs = (struct counting_jobs*)user_data;
  ++jobs->starts;
  job(job_data);
  jobs->last_handle = &jobs->starts;
  return jobs->last_handle;
}

static void jobs_wait(void* user_data, void* handle) {
  struct counting_jobs* jobs = (struct counting_jobs*)user_data;
  ++jobs->waits;
  CHECK(handle == jobs->last_handle);
}

static ocean_job_system counting_job_system(struct counting_jobs* jobs) {
  ocean_job_system system;
  memset(&system, 0, sizeof system);
  memset(jobs, 0, sizeof *jobs);
  system.struct_size = sizeof system;
  system.user_data = jobs;
  system.parallel_for = jobs_parallel_for;
  system.start_job = jobs_start;
  system.wait_job = jobs_wait;
  system.concurrency = 1;
  return system;
}

/* Options: the outputs, the frame index counted 1, 2, 3, the surface queries of the C++ API
 * reproduced exactly on the engine's job system, which the simulator must call. */
static void test_options(const struct reference* r) {
  ocean_config* config = reference_config(r);
  ocean_simulator* sim = NULL;
  ocean_simulator_options options;
  struct counting_jobs jobs;
  ocean_job_system system = counting_job_system(&jobs);
  double heights[MAX_POINTS], normals[3 * MAX_POINTS], velocities[3 * MAX_POINTS];
  uint64_t index = 0;
  size_t i;
  ocean_field_view v;
  memset(&options, 0x5a, sizeof options);
  ocean_simulator_options_init(&options);
  CHECK(options.struct_size == sizeof options && strcmp(options.backend, "cpu") == 0);
  CHECK(options.threads == 0 && options.job_system == NULL);
  CHECK(options.outputs == OCEAN_OUTPUT_DEFAULT);
  options.outputs = OCEAN_OUTPUT_DEFAULT | OCEAN_OUTPUT_VELOCITY;
  options.job_system = &system;
  OK(ocean_simulator_create_with_options(config, &options, &sim));
  CHECK(jobs.loops == 0); /* configuring runs nothing */
  OK(ocean_simulator_step(sim, r->time_s));
  CHECK(jobs.loops > 0 && jobs.ranges >= jobs.loops && jobs.indices >= jobs.ranges);
  OK(ocean_simulator_frame_time(sim, NULL, &index));
  CHECK(index == 1);
  OK(ocean_simulator_heights(sim, r->sx, r->sz, r->surfaces, heights));
  OK(ocean_simulator_normals(sim, r->sx, r->sz, r->surfaces, normals));
  OK(ocean_simulator_velocities(sim, r->sx, r->sz, r->surfaces, velocities));
  for (i = 0; i < r->surfaces; ++i) CHECK(heights[i] == r->sh[i]);
  for (i = 0; i < 3 * r->surfaces; ++i) CHECK(normals[i] == r->normal[i]);
  for (i = 0; i < 3 * r->surfaces; ++i) CHECK(velocities[i] == r->velocity[i]);
  {
    /* The reference is a sea, not zeros: upward normals with some tilt, moving water. */
    double tilt = 0.0, speed = 0.0;
    for (i = 0; i < r->surfaces; ++i) {
      CHECK(r->normal[3 * i + 1] > 0.5);
      tilt = fmax(tilt, fabs(r->normal[3 * i]) + fabs(r->normal[3 * i + 2]));
      speed = fmax(speed, fabs(r->velocity[3 * i]) + fabs(r->velocity[3 * i + 1]));
    }
    CHECK(tilt > 0.01 && speed > 0.05);
  }
  memset(&v, 0, sizeof v);
  v.struct_size = sizeof v;
  OK(ocean_simulator_field(sim, 0, OCEAN_FIELD_VELOCITY, 0, &v));
  CHECK(v.channels == 3 && v.element == OCEAN_ELEMENT_FLOAT32 && v.width == 32);
  /* Frames are counted 1, 2, 3, stepped or kicked; the kicked one ran through start/wait_job. */
  OK(ocean_simulator_step(sim, r->time_s + 1.0));
  OK(ocean_simulator_frame_time(sim, NULL, &index));
  CHECK(index == 2);
  OK(ocean_simulator_kick(sim, r->time_s + 2.0));
  OK(ocean_simulator_wait(sim));
  OK(ocean_simulator_frame_time(sim, NULL, &index));
  CHECK(index == 3);
  CHECK(jobs.starts == 1 && jobs.waits == 1);
  ocean_simulator_destroy(sim);
  sim = NULL;

  /* Without a job system: threads 0 (every hardware thread) and 1; NULL options = defaults. */
  options.job_system = NULL;
  options.threads = 1;
  OK(ocean_simulator_create_with_options(config, &options, &sim));
  OK(ocean_simulator_step(sim, r->time_s));
  OK(ocean_simulator_velocities(sim, r->sx, r->sz, r->surfaces, velocities));
  for (i = 0; i < 3 * r->surfaces; ++i) CHECK(velocities[i] == r->velocity[i]);
  ocean_simulator_destroy(sim);
  sim = NULL;
  options.threads = 0;
  OK(ocean_simulator_create_with_options(config, &options, &sim));
  ocean_simulator_destroy(sim);
  sim = NULL;
  OK(ocean_simulator_create_with_options(config, NULL, &sim));
  OK(ocean_simulator_step(sim, r->time_s));
  ERROR(ocean_simulator_velocities(sim, r->sx, r->sz, r->surfaces, velocities), OCEAN_UNSUPPORTED,
        "ocean_simulator_velocities: the simulator does not compute the velocity");
  ERROR(ocean_simulator_field(sim, 0, OCEAN_FIELD_VELOCITY, 0, &v), OCEAN_UNSUPPORTED,
        "velocity field is not computed");
  OK(ocean_simulator_normals(sim, r->sx, r->sz, r->surfaces, normals));
  for (i = 0; i < 3 * r->surfaces; ++i) CHECK(normals[i] == r->normal[i]);
  ocean_simulator_destroy(sim);
  ocean_config_destroy(config);
}

static void test_option_errors(void) {
  ocean_config* config = NULL;
  ocean_simulator* sim = NULL;
  ocean_simulator_options options;
  struct counting_jobs jobs;
  ocean_job_system system = counting_job_system(&jobs);
  double x[2] = {1.0, NAN}, z[2] = {0.0, 0.0}, out[6] = {-7.0, -7.0, -7.0, -7.0, -7.0, -7.0};
  OK(ocean_config_create(&config));
  OK(ocean_config_set(config, "resolution=16"));
  ocean_simulator_options_init(&options);
  options.struct_size = 0;
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "options->struct_size = 0 is too small");
  ocean_simulator_options_init(&options);
  options.threads = -1;
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "options->threads = -1 is out of range: must be 0 (every hardware thread) to 256");
  options.threads = 2;
  options.job_system = &system;
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "threads = 2 with a job system");
  options.threads = 0;
  options.outputs = 16;
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "options->outputs = 16 has unknown bits");
  options.outputs = OCEAN_OUTPUT_DEFAULT;
  options.backend = NULL;
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "options->backend is NULL");
  options.backend = "cpu";
  system.struct_size = 8;
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "job_system->struct_size = 8 is too small");
  system.struct_size = sizeof system;
  system.parallel_for = NULL;
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "job_system->parallel_for is NULL");
  system.parallel_for = jobs_parallel_for;
  system.wait_job = NULL;
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "start_job and wait_job must be given together");
  system.wait_job = jobs_wait;
  system.concurrency = 0;
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "job_system->concurrency = 0 is out of range: must be 1 to 256");
  system.concurrency = 1;
  ERROR(ocean_simulator_create_with_options(NULL, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "ocean_simulator_create_with_options: config is NULL");
  ERROR(ocean_simulator_create_with_options(config, &options, NULL), OCEAN_INVALID_ARGUMENT,
        "out is NULL");
  options.outputs = OCEAN_OUTPUT_VELOCITY;
  options.backend = "vulkan"; /* refused at configure, or no Vulkan at all */
  CHECK(ocean_simulator_create_with_options(config, &options, &sim) == OCEAN_UNSUPPORTED);
  options.backend = "nope";
  ERROR(ocean_simulator_create_with_options(config, &options, &sim), OCEAN_INVALID_ARGUMENT,
        "backend = 'nope' is unknown");
  CHECK(sim == NULL && jobs.loops == 0);
  options.backend = "cpu";
  OK(ocean_simulator_create_with_options(config, &options, &sim));
  OK(ocean_simulator_step(sim, 1.0));
  CHECK(jobs.loops > 0);
  ERROR(ocean_simulator_normals(sim, x, z, 2, out), OCEAN_INVALID_ARGUMENT, "x[1] = nan");
  ERROR(ocean_simulator_velocities(sim, x, z, 2, out), OCEAN_INVALID_ARGUMENT, "x[1] = nan");
  x[1] = INFINITY;
  ERROR(ocean_simulator_velocities(sim, x, z, 2, out), OCEAN_INVALID_ARGUMENT, "x[1] = inf");
  CHECK(out[0] == -7.0 && out[5] == -7.0); /* nothing written */
  ERROR(ocean_simulator_normals(sim, x, z, 2, NULL), OCEAN_INVALID_ARGUMENT, "normals is NULL");
  ERROR(ocean_simulator_velocities(sim, NULL, z, 2, out), OCEAN_INVALID_ARGUMENT, "x is NULL");
  ERROR(ocean_simulator_velocities(NULL, x, z, 2, out), OCEAN_INVALID_ARGUMENT,
        "ocean_simulator_velocities: simulator is NULL");
  ERROR(ocean_simulator_normals(NULL, x, z, 2, out), OCEAN_INVALID_ARGUMENT,
        "ocean_simulator_normals: simulator is NULL");
  OK(ocean_simulator_velocities(sim, x, z, 0, NULL)); /* nothing to do */
  ocean_simulator_options_init(NULL);                 /* ignored */
  ocean_simulator_destroy(sim);
  ocean_config_destroy(config);
}

static void test_errors(const char* tmpdir) {
  ocean_config* config = NULL;
  ocean_simulator* sim = NULL;
  ocean_field_view v;
  ocean_spectrum_params p;
  double x[2] = {1.0, NAN}, z[2] = {0.0, 0.0}, h[2] = {-7.0, -7.0}, omega = 1.0, s = -7.0;
  char before[4096], after[4096], path[512];
  size_t length = 0;
  OK(ocean_config_create(&config));
  OK(ocean_config_set(config, "resolution=16"));
  OK(ocean_config_to_json(config, before, sizeof before, &length));
  ERROR(ocean_config_merge_preset(config, "no-such-preset"), OCEAN_INVALID_ARGUMENT,
        "--preset = no-such-preset is neither a file nor a preset: must be calm, moderate, storm");
  ERROR(ocean_config_set(config, "sea.no_such_key=1"), OCEAN_INVALID_ARGUMENT,
        "sea.no_such_key: unknown key");
  ERROR(ocean_config_set(config, "resolution=100"), OCEAN_INVALID_ARGUMENT, "resolution = 100");
  ERROR(ocean_config_set(config, "novalue"), OCEAN_INVALID_ARGUMENT,
        "--set 'novalue': expected key=value");
  OK(ocean_config_to_json(config, after, sizeof after, &length));
  CHECK(strcmp(before, after) == 0);    /* failed changes left nothing behind */
  CHECK(ocean_last_error()[0] == '\0'); /* a success clears the message */
  ERROR(ocean_config_set(NULL, "seed=1"), OCEAN_INVALID_ARGUMENT,
        "ocean_config_set: config is NULL");
  ERROR(ocean_config_merge_preset(config, NULL), OCEAN_INVALID_ARGUMENT, "name_or_path is NULL");
  ERROR(ocean_config_create(NULL), OCEAN_INVALID_ARGUMENT, "out is NULL");
  snprintf(path, sizeof path, "%s/no/such/dir/p.json", tmpdir);
  ERROR(ocean_config_save(config, path), OCEAN_IO_ERROR, "No such file or directory");

  ERROR(ocean_simulator_create(config, "warp", &sim), OCEAN_INVALID_ARGUMENT,
        "backend = 'warp' is unknown");
  /* Built without CUDA, or no usable NVIDIA device ("no CUDA device: ..."). */
  ERROR(ocean_simulator_create(config, "cuda", &sim), OCEAN_UNSUPPORTED, "CUDA");
  CHECK(sim == NULL);
  {
    ocean_status vulkan = ocean_simulator_create(config, "vulkan", &sim);
    CHECK(vulkan == OCEAN_OK || vulkan == OCEAN_UNSUPPORTED);
    if (vulkan == OCEAN_OK) OK(ocean_simulator_step(sim, 1.0));
    ocean_simulator_destroy(sim);
    sim = NULL;
  }
  ERROR(ocean_simulator_step(NULL, 0.0), OCEAN_INVALID_ARGUMENT,
        "ocean_simulator_step: simulator is NULL");
  OK(ocean_simulator_create(config, "cpu", &sim));
  ERROR(ocean_simulator_step(sim, NAN), OCEAN_INVALID_ARGUMENT,
        "time_s = nan is out of range: must be a finite number");
  ERROR(ocean_simulator_kick(sim, INFINITY), OCEAN_INVALID_ARGUMENT, "time_s = inf");
  ERROR(ocean_simulator_heights(sim, x, z, 2, h), OCEAN_INVALID_ARGUMENT, "x[1] = nan");
  CHECK(h[0] == -7.0); /* nothing written */
  x[1] = 1e300;
  ERROR(ocean_simulator_heights(sim, x, z, 2, h), OCEAN_INVALID_ARGUMENT, "x[1] = 1e+300");
  ERROR(ocean_simulator_heights(sim, x, NULL, 2, h), OCEAN_INVALID_ARGUMENT, "z is NULL");
  ERROR(ocean_simulator_heights(NULL, x, z, 2, h), OCEAN_INVALID_ARGUMENT, "simulator is NULL");
  ERROR(ocean_simulator_cascade_count(sim, NULL), OCEAN_INVALID_ARGUMENT, "count is NULL");
  memset(&v, 0, sizeof v);
  ERROR(ocean_simulator_field(sim, 0, OCEAN_FIELD_DISPLACEMENT, 0, &v), OCEAN_INVALID_ARGUMENT,
        "struct_size = 0");
  v.struct_size = sizeof v;
  ERROR(ocean_simulator_field(sim, 3, OCEAN_FIELD_DISPLACEMENT, 0, &v), OCEAN_INVALID_ARGUMENT,
        "cascade = 3 is out of range: must be 0 to 2");
  ERROR(ocean_simulator_field(sim, 0, OCEAN_FIELD_PACKED, 5, &v), OCEAN_INVALID_ARGUMENT,
        "level = 5 is out of range: must be 0 to 4");
  ERROR(ocean_simulator_field(sim, 0, OCEAN_FIELD_FOAM, 1, &v), OCEAN_INVALID_ARGUMENT,
        "level = 1");
  ERROR(ocean_simulator_field(sim, 0, (ocean_field)99, 0, &v), OCEAN_INVALID_ARGUMENT,
        "field = 99");
  CHECK(v.data == NULL); /* outputs untouched on failure */
  ocean_simulator_destroy(sim);
  ocean_config_destroy(config);
  ocean_simulator_destroy(NULL);
  ocean_config_destroy(NULL);

  memset(&p, 0, sizeof p);
  ERROR(ocean_spectrum_evaluate(&p, &omega, 1, &s), OCEAN_INVALID_ARGUMENT,
        "params->struct_size = 0");
  ocean_spectrum_params_init(&p);
  p.model = "nope";
  ERROR(ocean_spectrum_evaluate(&p, &omega, 1, &s), OCEAN_INVALID_ARGUMENT, "model = 'nope'");
  p.model = "pierson-moskowitz";
  p.hs_m = -1.0;
  p.tp_s = 8.0;
  ERROR(ocean_spectrum_evaluate(&p, &omega, 1, &s), OCEAN_INVALID_ARGUMENT,
        "significant_wave_height_m = -1 is out of range");
  p.hs_m = 2.0;
  omega = NAN;
  ERROR(ocean_spectrum_evaluate(&p, &omega, 1, &s), OCEAN_INVALID_ARGUMENT, "omega[0] = nan");
  omega = -1.0;
  ERROR(ocean_spectrum_evaluate(&p, &omega, 1, &s), OCEAN_INVALID_ARGUMENT, "omega[0] = -1");
  CHECK(s == -7.0);
  ERROR(ocean_spectrum_evaluate(NULL, &omega, 1, &s), OCEAN_INVALID_ARGUMENT, "params is NULL");
}

/* The log hook's record: the messages of each level, the last one's text. */
struct log_record {
  int errors, infos;
  char last[512];
};
static void record_log(void* user_data, ocean_log_level level, const char* message) {
  struct log_record* r = (struct log_record*)user_data;
  if (level == OCEAN_LOG_ERROR) ++r->errors;
  if (level == OCEAN_LOG_INFO) ++r->infos;
  strncpy(r->last, message, sizeof r->last - 1);
  r->last[sizeof r->last - 1] = '\0';
}

/* A host allocator that counts: blocks from malloc, aligned by hand (C99 has no aligned
 * allocation), the original pointer kept in front of the block. */
struct counting_allocator {
  size_t allocations, deallocations, live_bytes, misaligned, wrong_size;
  int refuse; /* return NULL: out of memory */
};
static void* counting_allocate(void* user_data, size_t size, size_t alignment) {
  struct counting_allocator* c = (struct counting_allocator*)user_data;
  unsigned char* raw;
  size_t address;
  if (c->refuse) return NULL;
  raw = (unsigned char*)malloc(size + alignment + 2 * sizeof(size_t) + sizeof(void*));
  if (raw == NULL) return NULL;
  address = ((size_t)(raw + sizeof(void*) + 2 * sizeof(size_t)) + alignment - 1) & ~(alignment - 1);
  ((void**)address)[-1] = raw;
  ((size_t*)((void**)address - 1))[-1] = size;
  ++c->allocations;
  c->live_bytes += size;
  if ((alignment & (alignment - 1)) != 0 || (alignment != 64 && alignment != (2u << 20)))
    ++c->misaligned;
  return (void*)address;
}
static void counting_deallocate(void* user_data, void* pointer, size_t size, size_t alignment) {
  struct counting_allocator* c = (struct counting_allocator*)user_data;
  void** slot = (void**)pointer - 1;
  if (((size_t*)slot)[-1] != size) ++c->wrong_size;
  if (((size_t)pointer & (alignment - 1)) != 0) ++c->misaligned;
  ++c->deallocations;
  c->live_bytes -= size;
  free(*slot);
}

/* The hooks: every failed call's message to the log, a simulator's description on creation; the
 * reference's heights reproduced exactly on the host's memory, every block given back with its
 * size; no change of allocator while a simulator lives; a host without memory is
 * OCEAN_OUT_OF_MEMORY with nothing leaked. */
static void test_hooks(const struct reference* r) {
  struct log_record log;
  struct counting_allocator counts;
  ocean_allocator allocator;
  ocean_config* config = reference_config(r);
  ocean_simulator* sim = NULL;
  double heights[MAX_POINTS];
  size_t i;
  memset(&log, 0, sizeof log);
  memset(&counts, 0, sizeof counts);
  ocean_set_log_callback(record_log, &log);
  ERROR(ocean_config_set(config, "nokey=1"), OCEAN_INVALID_ARGUMENT, "nokey: unknown key");
  CHECK(log.errors == 1 && strcmp(log.last, ocean_last_error()) == 0);

  allocator.struct_size = sizeof allocator;
  allocator.user_data = &counts;
  allocator.allocate = counting_allocate;
  allocator.deallocate = counting_deallocate;
  OK(ocean_set_allocator(&allocator));
  OK(ocean_simulator_create(config, "cpu", &sim));
  CHECK(log.infos == 1 && strstr(log.last, "simulator: cpu backend, ") != NULL &&
        strstr(log.last, " thread") != NULL);
  CHECK(counts.allocations > 0 && counts.live_bytes > 0);
  ERROR(ocean_set_allocator(NULL), OCEAN_INVALID_ARGUMENT, "large arrays are live");
  OK(ocean_simulator_step(sim, r->time_s));
  OK(ocean_simulator_heights(sim, r->x, r->z, r->points, heights));
  for (i = 0; i < r->points; ++i) CHECK(heights[i] == r->h[i]);
  ocean_simulator_destroy(sim);
  CHECK(counts.deallocations == counts.allocations && counts.live_bytes == 0);
  CHECK(counts.misaligned == 0 && counts.wrong_size == 0);

  counts.refuse = 1;
  sim = NULL;
  ERROR(ocean_simulator_create(config, "cpu", &sim), OCEAN_OUT_OF_MEMORY, "out of memory");
  CHECK(sim == NULL && counts.deallocations == counts.allocations);
  OK(ocean_set_allocator(NULL));

  allocator.struct_size = 4;
  ERROR(ocean_set_allocator(&allocator), OCEAN_INVALID_ARGUMENT, "struct_size = 4");
  allocator.struct_size = sizeof allocator;
  allocator.deallocate = NULL;
  ERROR(ocean_set_allocator(&allocator), OCEAN_INVALID_ARGUMENT, "allocator->deallocate is NULL");
  CHECK(log.errors == 5);
  ocean_set_log_callback(NULL, NULL);
  ERROR(ocean_set_allocator(&allocator), OCEAN_INVALID_ARGUMENT, "deallocate is NULL");
  CHECK(log.errors == 5); /* silent again */
  ocean_config_destroy(config);
}

int main(int argc, char** argv) {
  struct reference r;
  if (argc != 3 || !read_reference(argv[1], &r)) {
    fprintf(stderr, "usage: capi_test REFERENCE.txt TMPDIR (REFERENCE.txt from capi_reference)\n");
    return 2;
  }
  CHECK(ocean_abi_version() == OCEAN_ABI_VERSION);
  CHECK(ocean_version() == OCEAN_VERSION);
  CHECK(strchr(ocean_version_string(), '.') != NULL);
  CHECK(strcmp(ocean_status_name(OCEAN_UNSUPPORTED), "unsupported") == 0);
  test_reference(&r);
  test_fields();
  test_presets(argv[2]);
  test_errors(argv[2]);
  test_options(&r);
  test_option_errors();
  test_hooks(&r);
  if (failures != 0) fprintf(stderr, "capi_test: %d check(s) failed\n", failures);
  return failures == 0 ? 0 : 1;
}
