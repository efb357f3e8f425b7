/* ocean/ocean.h — the stable C ABI of the ocean library (libocean_c.so): presets, a simulator
 * stepped in time (on its own threads or an engine's job system), its fields as pointers with a
 * layout (or, on an engine's Vulkan device or on CUDA, as GPU images and device pointers), batched
 * height, normal and particle-velocity queries and the one-sided wave spectrum S(ω). Pure C99,
 * no GPU header; callable from C, C#, Rust, Python ctypes, Godot...
 * The contract in full, with an example: docs/capi.md.
 *
 * Errors: every function that can fail returns an ocean_status. OCEAN_OK is 0; any other value
 * leaves the outputs untouched and sets this thread's last error message (ocean_last_error): one
 * line, the text the `ocean` tool prints after "ocean: error: " for the same input. A success
 * clears it. Null handles, null pointers and non-finite numbers are OCEAN_INVALID_ARGUMENT, never
 * a crash. No C++ exception leaves the library (out of memory is OCEAN_OUT_OF_MEMORY).
 *
 * Lifetimes: each *_create has one *_destroy (which accepts NULL). Strings passed in are copied
 * or read during the call only. Pointers returned by ocean_simulator_field stay valid until the
 * next ocean_simulator_step / ocean_simulator_wait / ocean_simulator_destroy on that simulator.
 *
 * Threading: a handle is used by one thread at a time (no internal locking); distinct handles may
 * be used from distinct threads at once. The last error is per thread. A simulator runs its
 * frames on oneTBB's threads, or on the engine's job system (ocean_simulator_options).
 *
 * Versioning: OCEAN_ABI_VERSION is the soname (libocean_c.so.<abi>); it changes only when a
 * function or struct changes incompatibly. Within one ABI version functions and enum values are
 * only added, and structs grow only at their end: each struct starts with `struct_size`, set by
 * the caller to sizeof, so the library knows which fields the caller has.
 *
 * Units are SI (metres, seconds, radians); Y is up; a cascade is a periodic square patch of side
 * L sampled on N × N texels, texel (col, row) starting at world (x, z) = (col·L/N, row·L/N). */
#ifndef OCEAN_OCEAN_H
#define OCEAN_OCEAN_H

#include <stddef.h>
#include <stdint.h>

#if defined(OCEAN_C_BUILDING)
#define OCEAN_API __attribute__((visibility("default")))
#else
#define OCEAN_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- version ------------------------------------------------------------------------------ */

#define OCEAN_VERSION_MAJOR 0
#define OCEAN_VERSION_MINOR 1
#define OCEAN_VERSION_PATCH 0
/** major·10000 + minor·100 + patch of this header. */
#define OCEAN_VERSION \
  (OCEAN_VERSION_MAJOR * 10000 + OCEAN_VERSION_MINOR * 100 + OCEAN_VERSION_PATCH)
/** The ABI this header describes; a library with another ABI version is not compatible. */
#define OCEAN_ABI_VERSION 1

/** OCEAN_VERSION of the library loaded at run time. */
OCEAN_API uint32_t ocean_version(void);
/** The library's version as "major.minor.patch" (static storage). */
OCEAN_API const char* ocean_version_string(void);
/** OCEAN_ABI_VERSION of the library loaded at run time; compare it with the header's. */
OCEAN_API uint32_t ocean_abi_version(void);

/* ---- status ------------------------------------------------------------------------------- */

typedef enum ocean_status {
  OCEAN_OK = 0,
  OCEAN_INVALID_ARGUMENT = 1,        /**< a bad value, name, key, handle or pointer */
  OCEAN_IO_ERROR = 2,                /**< a file could not be read or written */
  OCEAN_UNSUPPORTED = 3,             /**< not compiled in, or not available on this machine */
  OCEAN_INTERNAL = 4,                /**< a bug in the library */
  OCEAN_CANCELLED = 5,               /**< stopped at the caller's request */
  OCEAN_OUT_OF_MEMORY = 6,           /**< an allocation failed */
  OCEAN_STATUS_MAX_ENUM = 0x7FFFFFFF /**< not a status: keeps the enum 32 bits wide */
} ocean_status;

/** The calling thread's message of the last failed call ("" after a success); one line, no
 *  newline. Valid until the thread's next call into the library. Never NULL. */
OCEAN_API const char* ocean_last_error(void);
/** The status's name, e.g. "invalid_argument" (static storage; "unknown" for other values). */
OCEAN_API const char* ocean_status_name(ocean_status status);

/* ---- hooks: where messages and memory go -------------------------------------------------- */

typedef enum ocean_log_level {
  OCEAN_LOG_ERROR = 0,                  /**< a call failed: the text of ocean_last_error */
  OCEAN_LOG_WARNING = 1,                /**< something the caller may want to change */
  OCEAN_LOG_INFO = 2,                   /**< what a simulator was made with */
  OCEAN_LOG_LEVEL_MAX_ENUM = 0x7FFFFFFF /**< not a level: keeps the enum 32 bits wide */
} ocean_log_level;

/** Receives the library's messages: one line, no newline, valid during the call only. Called on
 *  the thread of the call that has something to say, so it must be thread-safe where the
 *  library is used from several threads; it must not call back into the library. */
typedef void (*ocean_log_fn)(void* user_data, ocean_log_level level, const char* message);

/** Sends every message to `log` (NULL: none, the default): each failed call's error (ERROR,
 *  also in ocean_last_error) and, for each simulator made, its backend, cascades, resolution
 *  and threads (INFO). Process-wide; may be called at any time, from any thread (a message being
 *  delivered goes to the callback it started with). */
OCEAN_API void ocean_set_log_callback(ocean_log_fn log, void* user_data);

/** An engine's allocator for the simulation's large arrays: each cascade's spectrum state, FFT
 *  planes and frame outputs (ocean/memory.hpp; the memory that grows with resolution and
 *  cascades). The small bookkeeping stays on the C++ heap.
 *
 *  allocate(user_data, size, alignment) returns `size` bytes aligned to `alignment` (a power of
 *  two: 64, or 2 MiB for arrays of 1 MiB and up, whose size is then a multiple of 2 MiB), or NULL
 *  when it has none: the call that needed it fails with OCEAN_OUT_OF_MEMORY. deallocate(user_data,
 *  pointer, size, alignment) takes back a block with the size and alignment it was made with.
 *  Both may be called on any thread the simulator runs on. */
typedef struct ocean_allocator {
  size_t struct_size; /**< set by the caller: sizeof(ocean_allocator) */
  void* user_data;    /**< passed as the first argument of both functions */
  void* (*allocate)(void* user_data, size_t size, size_t alignment);
  void (*deallocate)(void* user_data, void* pointer, size_t size, size_t alignment);
} ocean_allocator;

/** Makes the large arrays of every simulator created from now on with `allocator` (copied;
 *  user_data must stay valid while any of them lives), or with the library's own again (NULL).
 *  Only while no array exists: OCEAN_INVALID_ARGUMENT while any simulator (or anything else
 *  holding such arrays in the process) lives, since each array goes back to the allocator that
 *  made it; also for a struct_size too small or a missing function. Process-wide. */
OCEAN_API ocean_status ocean_set_allocator(const ocean_allocator* allocator);

/* ---- presets: a configuration assembled in layers ----------------------------------------- */

/** A simulation configuration (defaults ← presets ← key=value overrides), always valid. */
typedef struct ocean_config ocean_config;

/** A configuration holding the library's defaults. */
OCEAN_API ocean_status ocean_config_create(ocean_config** out);
OCEAN_API void ocean_config_destroy(ocean_config* config);
/** Merges a built-in preset ("calm", "moderate", "storm") or a preset JSON file over the
 *  configuration, as `ocean --preset`. On error the configuration is unchanged. */
OCEAN_API ocean_status ocean_config_merge_preset(ocean_config* config, const char* name_or_path);
/** Sets one key, as `ocean --set`: "dotted.key=value", the value JSON or a bare string
 *  ("sea.wind_sea.fetch_m=5e4", "normals=analytic"). An unknown key or a value out of range is
 *  an error and leaves the configuration unchanged. */
OCEAN_API ocean_status ocean_config_set(ocean_config* config, const char* assignment);
/** The configuration as a preset document (two-space indent, keys in a fixed order, numbers that
 *  read back exactly), snprintf-style: writes at most `capacity` bytes including the final NUL
 *  into `buffer` (which may be NULL when capacity is 0) and sets *length to the full length
 *  without the NUL. A buffer too small is not an error: compare *length with capacity. */
OCEAN_API ocean_status ocean_config_to_json(const ocean_config* config, char* buffer,
                                            size_t capacity, size_t* length);
/** Writes the preset document to `path`, replacing it atomically (never a partial file). */
OCEAN_API ocean_status ocean_config_save(const ocean_config* config, const char* path);
/** The number of built-in presets, and the name of the i-th (static storage; NULL past the end). */
OCEAN_API size_t ocean_builtin_preset_count(void);
OCEAN_API const char* ocean_builtin_preset_name(size_t index);

/* ---- the simulator ------------------------------------------------------------------------ */

typedef struct ocean_simulator ocean_simulator;

/** Configures a simulator of `config` (copied) on a backend: "cpu" or "vulkan" (see `ocean
 *  info`). A backend not built in or with no device is OCEAN_UNSUPPORTED; an unknown name is
 *  OCEAN_INVALID_ARGUMENT. Allocates every buffer; until the first step the published frame is
 *  zeros at time 0. */
OCEAN_API ocean_status ocean_simulator_create(const ocean_config* config, const char* backend,
                                              ocean_simulator** out);
OCEAN_API void ocean_simulator_destroy(ocean_simulator* simulator);
/** Computes and publishes the frame at time_s (finite). Does not allocate. */
OCEAN_API ocean_status ocean_simulator_step(ocean_simulator* simulator, double time_s);
/** Starts the frame at time_s in the background; the published frame (and its field pointers)
 *  stays readable until ocean_simulator_wait publishes the new one. */
OCEAN_API ocean_status ocean_simulator_kick(ocean_simulator* simulator, double time_s);
/** Waits for the kicked frame and publishes it; nothing when none was kicked. */
OCEAN_API ocean_status ocean_simulator_wait(ocean_simulator* simulator);
/** The published frame's time, s, and its index (frames computed since configuration); either
 *  output may be NULL. */
OCEAN_API ocean_status ocean_simulator_frame_time(const ocean_simulator* simulator, double* time_s,
                                                  uint64_t* index);
/** The number of cascades (patches, largest first). */
OCEAN_API ocean_status ocean_simulator_cascade_count(const ocean_simulator* simulator,
                                                     size_t* count);

typedef enum ocean_field {
  OCEAN_FIELD_DISPLACEMENT = 0,      /**< float32 ×3: (Dx, h, Dz), m */
  OCEAN_FIELD_DISPLACEMENT_HALF = 1, /**< float16 ×4: (Dx, h, Dz, 0), texture-ready */
  OCEAN_FIELD_NORMAL = 2,            /**< float32 ×3: unit normal of the displaced surface */
  OCEAN_FIELD_JACOBIAN = 3,          /**< float32 ×1: Jacobian J of the horizontal map */
  OCEAN_FIELD_FOAM = 4,              /**< float32 ×1: accumulated foam coverage in [0, 1] */
  /** uint8 ×4 per texel, bytes (normal x, normal z, foam or Jacobian, smoothness) in memory
   *  order, one mip level (level 0 is N × N, level l is (N >> l)²). */
  OCEAN_FIELD_PACKED = 5,
  /** float32 ×3: (u, w, v) = ∂(Dx, h, Dz)/∂t, m/s, the velocity of the surface particle that
   *  starts at the texel; computed only with OCEAN_OUTPUT_VELOCITY (CPU backend). */
  OCEAN_FIELD_VELOCITY = 6,
  /** Not a field: makes every int a value of the type (C++ limits an enum's values to the bits
   *  its enumerators need), so that a caller's out-of-range number is an error, not undefined. */
  OCEAN_FIELD_MAX_ENUM = 0x7FFFFFFF
} ocean_field;

typedef enum ocean_element_type {
  OCEAN_ELEMENT_FLOAT32 = 0,
  OCEAN_ELEMENT_FLOAT16 = 1, /**< IEEE 754 binary16 stored as uint16_t */
  OCEAN_ELEMENT_UINT8 = 2,
  OCEAN_ELEMENT_MAX_ENUM = 0x7FFFFFFF /**< not a type: keeps the enum 32 bits wide */
} ocean_element_type;

/** Where a field of the published frame lies in memory: texel (col, row), channel c is the
 *  element at (const char*)data + row·row_stride_bytes + (col·channels + c)·element size. */
typedef struct ocean_field_view {
  size_t struct_size;         /**< set by the caller: sizeof(ocean_field_view) */
  const void* data;           /**< read-only; valid until the next step, wait or destroy */
  int32_t width, height;      /**< texels */
  size_t row_stride_bytes;    /**< bytes from one row to the next */
  int32_t channels;           /**< elements per texel */
  ocean_element_type element; /**< type of one element */
  double patch_size_m;        /**< side L of the cascade's patch, m (of level 0) */
} ocean_field_view;

/** Fills *view for one field of cascade `cascade` (0 = largest). `level` is the mip level of
 *  OCEAN_FIELD_PACKED and must be 0 for the others. A field the configuration does not compute
 *  (outputs.normal = false...) is OCEAN_UNSUPPORTED. */
OCEAN_API ocean_status ocean_simulator_field(const ocean_simulator* simulator, size_t cascade,
                                             ocean_field field, int32_t level,
                                             ocean_field_view* view);

/** Heights, m, of the rendered surface above the world points (x[i], z[i]), i < count, for the
 *  published frame: the undisplaced point that the horizontal displacement carries onto (x, z)
 *  is found first (docs/math.md M.7.7). Every x[i], z[i] must be finite; `heights` receives count
 *  values. Thread-safe with other queries and with a kicked frame, not with step or wait. */
OCEAN_API ocean_status ocean_simulator_heights(const ocean_simulator* simulator, const double* x,
                                               const double* z, size_t count, double* heights);

/** Unit normals (nx[i], ny[i], nz[i]) of the rendered surface above (x[i], z[i]), i < count, for
 *  the published frame: (−∂η/∂x, 1, −∂η/∂z) normalised, η the height of
 *  ocean_simulator_heights at the same points. Arguments, checks and threading as
 *  ocean_simulator_heights; `normals` receives 3·count values. */
OCEAN_API ocean_status ocean_simulator_normals(const ocean_simulator* simulator, const double* x,
                                               const double* z, size_t count, double* normals);
/** Velocities (u[i], w[i], v[i]), m/s (x, y up, z), of the water particles at the surface above
 *  (x[i], z[i]), i < count, for the published frame (linear wave theory, docs/math.md M.7.11):
 *  w is the rate of rise of the surface following the particle. Needs the velocity output
 *  (OCEAN_OUTPUT_VELOCITY in ocean_simulator_options): without it OCEAN_UNSUPPORTED. Arguments,
 *  checks and threading as ocean_simulator_heights; `velocities` receives 3·count values. */
OCEAN_API ocean_status ocean_simulator_velocities(const ocean_simulator* simulator, const double* x,
                                                  const double* z, size_t count,
                                                  double* velocities);

/* ---- options: outputs and the job system -------------------------------------------------- */

/** The optional per-texel arrays a frame computes (a bit set of ocean_simulator_options::
 *  outputs). Without OCEAN_OUTPUT_NORMAL, _JACOBIAN, _FOAM the field is OCEAN_UNSUPPORTED; the
 *  displacement and the packed map are always computed. */
typedef enum ocean_output_flags {
  OCEAN_OUTPUT_NORMAL = 1,   /**< OCEAN_FIELD_NORMAL */
  OCEAN_OUTPUT_JACOBIAN = 2, /**< OCEAN_FIELD_JACOBIAN */
  OCEAN_OUTPUT_FOAM = 4,     /**< OCEAN_FIELD_FOAM */
  /** OCEAN_FIELD_VELOCITY and ocean_simulator_velocities: two more inverse FFTs per cascade and
   *  frame; CPU backend only (another backend is OCEAN_UNSUPPORTED at create). */
  OCEAN_OUTPUT_VELOCITY = 8,
  /** What ocean_simulator_create computes: normal, Jacobian and foam. */
  OCEAN_OUTPUT_DEFAULT = 7,
  OCEAN_OUTPUT_MAX_ENUM = 0x7FFFFFFF /**< not a flag: keeps the enum 32 bits wide */
} ocean_output_flags;

/** A body of ocean_job_system::parallel_for: processes indices [begin, end). */
typedef void (*ocean_job_range_fn)(void* job_data, size_t begin, size_t end);
/** A background job of ocean_job_system::start_job. */
typedef void (*ocean_job_fn)(void* job_data);

/** An engine's job system, which the simulator then runs all its work on instead of its own
 *  threads (oneTBB).
 *
 *  parallel_for (required) must call body(job_data, begin, end) over disjoint ranges that cover
 *  [0, count) exactly once, in chunks of about `grain` indices, on any threads and in any order,
 *  and return only when every call has returned. A body may itself call parallel_for (the
 *  simulator nests loops): that must neither deadlock nor wait for the outer loop. Bodies never
 *  call back into the C API and never fail.
 *
 *  start_job and wait_job (optional, both or neither) run the frame of ocean_simulator_kick in
 *  the background: start_job starts job(job_data) and returns a handle (any value, NULL
 *  included), wait_job(handle) returns once that job has finished. At most one job per simulator
 *  is in flight. Without them ocean_simulator_kick computes the frame before it returns.
 *
 *  concurrency is the number of threads the loops may run on, 1 to 256: the simulator sizes its
 *  work by it. The table is copied at create; user_data must stay valid until every simulator
 *  created with it is destroyed. */
typedef struct ocean_job_system {
  size_t struct_size; /**< set by the caller: sizeof(ocean_job_system) */
  void* user_data;    /**< passed as the first argument of every function below */
  void (*parallel_for)(void* user_data, size_t count, size_t grain, ocean_job_range_fn body,
                       void* job_data);
  void* (*start_job)(void* user_data, ocean_job_fn job, void* job_data);
  void (*wait_job)(void* user_data, void* handle);
  int32_t concurrency;
} ocean_job_system;

/** How ocean_simulator_create_with_options makes a simulator. */
typedef struct ocean_simulator_options {
  size_t struct_size;  /**< set by ocean_simulator_options_init: sizeof(ocean_simulator_options) */
  const char* backend; /**< "cpu" (the default) or "vulkan", as ocean_simulator_create */
  /** Threads of the library's own scheduler (oneTBB): 0 = every hardware thread, else 1 to 256.
   *  Must be 0 when job_system is set (the engine's threads are used). */
  int32_t threads;
  /** The engine's job system (copied at create), or NULL for the library's scheduler. */
  const ocean_job_system* job_system;
  uint32_t outputs; /**< ocean_output_flags; OCEAN_OUTPUT_DEFAULT after init */
} ocean_simulator_options;

/** Defaults: struct_size set, backend "cpu", threads 0, no job system, OCEAN_OUTPUT_DEFAULT. */
OCEAN_API void ocean_simulator_options_init(ocean_simulator_options* options);
/** ocean_simulator_create with options (NULL = the defaults): the outputs replace the
 *  configuration's, the work runs on `threads` threads or on the job system. An unknown output
 *  bit, threads out of range, threads with a job system, a job system without parallel_for or
 *  with only one of start_job and wait_job, concurrency < 1 and a struct_size too small are
 *  OCEAN_INVALID_ARGUMENT. */
OCEAN_API ocean_status ocean_simulator_create_with_options(const ocean_config* config,
                                                           const ocean_simulator_options* options,
                                                           ocean_simulator** out);

/* ---- GPU-resident outputs: an engine's Vulkan device, CUDA device pointers ---------------- */

/* The frame's outputs where the GPU computed them, for an engine to sample with no host copy:
 * a simulator made on the engine's own Vulkan device gives its output images as Vulkan handles;
 * one on the CUDA backend gives its arrays as device pointers. This header needs neither
 * vulkan.h nor cuda.h: dispatchable Vulkan handles (VkInstance, VkPhysicalDevice, VkDevice,
 * VkQueue) pass as void*, non-dispatchable ones (VkImage, VkImageView) as ocean_vk_handle, enum
 * and flag values as integers of Vulkan's numbering.
 *
 * Synchronisation (both APIs): the outputs hold the published frame once ocean_simulator_step or
 * ocean_simulator_wait has returned OCEAN_OK, until the next ocean_simulator_step or
 * ocean_simulator_kick starts overwriting them. Before returning, the library has waited on the
 * host for every command that wrote them (a VkFence; cudaStreamSynchronize), so no semaphore
 * passes between the two sides:
 *  - reading (read after write): any queue of the simulator's queue family, any CUDA stream of
 *    its device, may read after the call returns; Vulkan readers first record a memory barrier
 *    from (src_stage_mask, src_access_mask) of ocean_vulkan_image to their own stage and access,
 *    the image staying in its layout (GENERAL);
 *  - overwriting (write after read): the next step or kick must not start while the engine's
 *    reads of the frame may still run: wait for their fence (or stream) first, or, on the very
 *    queue the simulator was given, record after the reads an execution barrier from the reading
 *    stages to VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, which orders the library's later submission.
 *
 * Queue (Vulkan): the library submits on the given queue, which Vulkan requires to be externally
 * synchronised: the engine must not use it from another thread during ocean_simulator_create_
 * on_vulkan, _step, _wait, and from _kick until the matching _wait returns (the kicked frame is
 * submitted from a library thread). ocean_simulator_destroy calls vkDeviceWaitIdle: no queue of
 * the device may be in use then. Giving the library a queue of its own (another index of the
 * family) leaves only that last rule. */

/** A non-dispatchable Vulkan handle (VkImage, VkImageView) as a 64-bit integer: in C on a 64-bit
 *  target (VkImage)(uintptr_t)h, on a 32-bit one (VkImage)h (Vulkan defines it as uint64_t). */
typedef uint64_t ocean_vk_handle;

/** An engine's Vulkan objects for ocean_simulator_create_on_vulkan. The library destroys none of
 *  them: they must outlive the simulator (destroy it, then the device, then the instance). */
typedef struct ocean_vulkan_device {
  size_t struct_size;    /**< set by the caller: sizeof(ocean_vulkan_device) */
  void* instance;        /**< VkInstance, made through the system's Vulkan loader */
  void* physical_device; /**< VkPhysicalDevice: one of instance's, Vulkan 1.2 or later */
  void* device;          /**< VkDevice made from physical_device; no extension or feature needed */
  uint32_t queue_family; /**< the family of `queue`: must support compute */
  void* queue;           /**< VkQueue: vkGetDeviceQueue(device, queue_family, any index) */
  /** VkApplicationInfo::apiVersion the instance was made with: VK_API_VERSION_1_2 or later. */
  uint32_t api_version;
} ocean_vulkan_device;

/** ocean_simulator_create_with_options on the Vulkan backend, on the engine's `device` (checked:
 *  handles not NULL, the family in range with compute, Vulkan 1.2 on both sides; one line naming
 *  what is missing). options may be NULL (the defaults); its `backend` is not read (the backend
 *  is Vulkan), its outputs, threads and job system count as there (OCEAN_OUTPUT_VELOCITY is
 *  OCEAN_UNSUPPORTED: the Vulkan backend does not compute it). A build without Vulkan answers
 *  OCEAN_UNSUPPORTED. Uploads the spectra and records the frame on `queue` before it returns. */
OCEAN_API ocean_status ocean_simulator_create_on_vulkan(const ocean_config* config,
                                                        const ocean_vulkan_device* device,
                                                        const ocean_simulator_options* options,
                                                        ocean_simulator** out);

/** One output image of a simulator on the Vulkan backend. Layer c, mip level l holds cascade c's
 *  field at level l as ocean_simulator_field gives it, texel (col, row) at (x, y) = (col, row),
 *  up to the rounding of the device's conversion into the image format (one unit in the last
 *  place of half or of 8-bit unorm, where the device rounds otherwise than the library's packing
 *  does). The handles are valid until the simulator is
 *  destroyed and belong to its device (the engine's with ocean_simulator_create_on_vulkan). */
typedef struct ocean_vulkan_image {
  size_t struct_size;    /**< set by the caller: sizeof(ocean_vulkan_image) */
  ocean_vk_handle image; /**< VkImage: 2D, `layers` array layers, exclusive to the queue family */
  /** VkImageView: VK_IMAGE_VIEW_TYPE_2D_ARRAY over every layer and mip level, for sampling. */
  ocean_vk_handle view;
  /** VkFormat: VK_FORMAT_R16G16B16A16_SFLOAT (97) for OCEAN_FIELD_DISPLACEMENT_HALF,
   *  VK_FORMAT_R8G8B8A8_UNORM (37) for OCEAN_FIELD_PACKED. */
  int32_t format;
  uint32_t width, height; /**< texels of level 0: N × N */
  uint32_t layers;        /**< array layers: one per cascade (ocean_simulator_cascade_count) */
  uint32_t mip_levels;    /**< 1 for the displacement, log2(N) + 1 for the packed map */
  /** VkImageLayout the image is always in: VK_IMAGE_LAYOUT_GENERAL (1). Do not transition it. */
  int32_t layout;
  /** VkImageUsageFlags it was made with: STORAGE | SAMPLED | TRANSFER_SRC (0x1 | 0x4 | 0x8). */
  uint32_t usage;
  /** The library's last writes to it, the first scope of the engine's barrier before reading:
   *  VkPipelineStageFlags (VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT) and VkAccessFlags
   *  (VK_ACCESS_SHADER_WRITE_BIT). */
  uint32_t src_stage_mask;
  uint32_t src_access_mask;
  uint64_t frame_index; /**< the published frame it holds (as ocean_simulator_frame_time) */
} ocean_vulkan_image;

/** Fills *image for `field` of a simulator on the Vulkan backend: OCEAN_FIELD_DISPLACEMENT_HALF
 *  (half4 (Dx, h, Dz, 0), m) or OCEAN_FIELD_PACKED (RGBA8 (n_x, n_z, foam or Jacobian,
 *  smoothness), every mip level). The other fields live in device buffers the library reads back:
 *  OCEAN_UNSUPPORTED, as for a simulator on another backend or a build without Vulkan. A frame
 *  that failed on the device (device lost) is returned as that error. Synchronisation: above. */
OCEAN_API ocean_status ocean_simulator_vulkan_image(const ocean_simulator* simulator,
                                                    ocean_field field, ocean_vulkan_image* image);

/** The device pointer of one field of a simulator on the CUDA backend: *view as
 *  ocean_simulator_field fills it (same layout, struct_size set by the caller), but view->data
 *  is an address in the memory of CUDA device *device (an ordinal, for cudaSetDevice), which
 *  holds the published frame. Read it from any stream of that device (synchronisation: above);
 *  never write it. A simulator on another backend, and every simulator in a build without CUDA,
 *  is OCEAN_UNSUPPORTED (the message names the backend); OCEAN_FIELD_VELOCITY is not computed
 *  there. `device` may be NULL. */
OCEAN_API ocean_status ocean_simulator_cuda_field(const ocean_simulator* simulator, size_t cascade,
                                                  ocean_field field, int32_t level,
                                                  ocean_field_view* view, int32_t* device);

/* ---- sea-state spectra -------------------------------------------------------------------- */

/** The parameters of a one-sided frequency spectrum, as `ocean spectrum` takes them. Numbers left
 *  NaN are unset: give (hs_m, tp_s) or wind_speed_mps (with fetch_m for jonswap/tma). */
typedef struct ocean_spectrum_params {
  size_t struct_size;    /**< set by ocean_spectrum_params_init: sizeof(ocean_spectrum_params) */
  const char* model;     /**< "pierson-moskowitz", "jonswap", "tma" or "phillips" */
  double hs_m;           /**< significant wave height Hs, m (with tp_s) */
  double tp_s;           /**< peak period Tp, s */
  double wind_speed_mps; /**< U10 (U19.5 for pierson-moskowitz), m/s */
  double fetch_m;        /**< fetch F, m */
  double gamma;          /**< JONSWAP peak enhancement γ ≥ 1; NaN = automatic */
  double depth_m;        /**< water depth of tma, m; INFINITY = deep water */
  double gravity_mps2;   /**< g, m/s² */
} ocean_spectrum_params;

/** Defaults: struct_size set, model "jonswap", every sea-state number NaN, depth infinite,
 *  g = 9.81 m/s². */
OCEAN_API void ocean_spectrum_params_init(ocean_spectrum_params* params);
/** S(ω[i]), m²·s/rad, for i < count into `spectrum`; every ω ≥ 0 and finite. Parameter errors
 *  are those of `ocean spectrum`, e.g. "significant_wave_height_m = -1 is out of range: ...". */
OCEAN_API ocean_status ocean_spectrum_evaluate(const ocean_spectrum_params* params,
                                               const double* omega, size_t count, double* spectrum);

#ifdef __cplusplus
}
#endif

#endif /* OCEAN_OCEAN_H */
