"""The C ABI (include/ocean/ocean.h) called from Python through ctypes alone: libocean_c.so is
loaded by path, its functions declared here from the header, and the heights, normals,
velocities (through ocean_simulator_create_with_options) and spectrum of the C++ API's reference
scenario (written by capi_reference) reproduced exactly; error paths give a status and the
one-line message.

Standard library only. Usage: python3 capi_ctypes_test.py LIBOCEAN_C REFERENCE.txt
Exits 0 when every check passes, 1 otherwise."""
import ctypes
import math
import sys

OK, INVALID_ARGUMENT, UNSUPPORTED = 0, 1, 3
c_double_p = ctypes.POINTER(ctypes.c_double)


class SpectrumParams(ctypes.Structure):
    _fields_ = [("struct_size", ctypes.c_size_t), ("model", ctypes.c_char_p),
                ("hs_m", ctypes.c_double), ("tp_s", ctypes.c_double),
                ("wind_speed_mps", ctypes.c_double), ("fetch_m", ctypes.c_double),
                ("gamma", ctypes.c_double), ("depth_m", ctypes.c_double),
                ("gravity_mps2", ctypes.c_double)]


class SimulatorOptions(ctypes.Structure):
    _fields_ = [("struct_size", ctypes.c_size_t), ("backend", ctypes.c_char_p),
                ("threads", ctypes.c_int32), ("job_system", ctypes.c_void_p),
                ("outputs", ctypes.c_uint32)]


OUTPUT_DEFAULT, OUTPUT_VELOCITY = 7, 8


def load(path):
    lib = ctypes.CDLL(path)
    handle = ctypes.c_void_p
    sigs = {
        "ocean_abi_version": (ctypes.c_uint32, []),
        "ocean_last_error": (ctypes.c_char_p, []),
        "ocean_config_create": (ctypes.c_int, [ctypes.POINTER(handle)]),
        "ocean_config_destroy": (None, [handle]),
        "ocean_config_merge_preset": (ctypes.c_int, [handle, ctypes.c_char_p]),
        "ocean_config_set": (ctypes.c_int, [handle, ctypes.c_char_p]),
        "ocean_simulator_create": (ctypes.c_int, [handle, ctypes.c_char_p,
                                                  ctypes.POINTER(handle)]),
        "ocean_simulator_destroy": (None, [handle]),
        "ocean_simulator_step": (ctypes.c_int, [handle, ctypes.c_double]),
        "ocean_simulator_heights": (ctypes.c_int, [handle, c_double_p, c_double_p,
                                                   ctypes.c_size_t, c_double_p]),
        "ocean_simulator_normals": (ctypes.c_int, [handle, c_double_p, c_double_p,
                                                   ctypes.c_size_t, c_double_p]),
        "ocean_simulator_velocities": (ctypes.c_int, [handle, c_double_p, c_double_p,
                                                      ctypes.c_size_t, c_double_p]),
        "ocean_simulator_options_init": (None, [ctypes.POINTER(SimulatorOptions)]),
        "ocean_simulator_create_with_options": (ctypes.c_int, [handle,
                                                               ctypes.POINTER(SimulatorOptions),
                                                               ctypes.POINTER(handle)]),
        "ocean_spectrum_params_init": (None, [ctypes.POINTER(SpectrumParams)]),
        "ocean_spectrum_evaluate": (ctypes.c_int, [ctypes.POINTER(SpectrumParams), c_double_p,
                                                   ctypes.c_size_t, c_double_p]),
    }
    for name, (restype, argtypes) in sigs.items():
        function = getattr(lib, name)
        function.restype, function.argtypes = restype, argtypes
    return lib


def read_reference(path):
    ref = {"sets": [], "points": [], "spectrum": [], "surface": []}
    with open(path) as f:
        for line in f:
            words = line.split()
            if words[0] in ("preset", "time"):
                ref[words[0]] = words[1] if words[0] == "preset" else float(words[1])
            elif words[0] == "set":
                ref["sets"].append(words[1])
            elif words[0] == "height":
                ref["points"].append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "surface":
                ref["surface"].append(tuple(float(w) for w in words[1:10]))
            elif words[0] == "spectrum":
                ref["spectrum"].append((words[1],) + tuple(float(w) for w in words[2:6]))
    return ref


class Checks:
    def __init__(self, lib):
        self.lib, self.failures = lib, 0

    def check(self, condition, what):
        if not condition:
            print("capi_ctypes_test: FAILED: " + what, file=sys.stderr)
            self.failures += 1

    def ok(self, status, what):
        self.check(status == OK, "%s -> %d: %s" % (what, status, self.message()))

    def error(self, status, expected, fragment, what):
        message = self.message()
        self.check(status == expected and fragment in message and "\n" not in message,
                   "%s -> %d %r, expected %d with %r" % (what, status, message, expected,
                                                         fragment))

    def message(self):
        return self.lib.ocean_last_error().decode("utf-8")


def doubles(values):
    return (ctypes.c_double * len(values))(*values)


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    lib = load(argv[1])
    ref = read_reference(argv[2])
    t = Checks(lib)
    t.check(lib.ocean_abi_version() == 1, "ABI version 1")

    config, sim = ctypes.c_void_p(), ctypes.c_void_p()
    t.ok(lib.ocean_config_create(ctypes.byref(config)), "config_create")
    t.ok(lib.ocean_config_merge_preset(config, ref["preset"].encode()), "merge_preset")
    for assignment in ref["sets"]:
        t.ok(lib.ocean_config_set(config, assignment.encode()), "set " + assignment)
    t.ok(lib.ocean_simulator_create(config, b"cpu", ctypes.byref(sim)), "simulator_create")
    t.ok(lib.ocean_simulator_step(sim, ref["time"]), "step")
    n = len(ref["points"])
    x = doubles([p[0] for p in ref["points"]])
    z = doubles([p[1] for p in ref["points"]])
    heights = (ctypes.c_double * n)()
    t.ok(lib.ocean_simulator_heights(sim, x, z, n, heights), "heights")
    for i, (px, pz, h) in enumerate(ref["points"]):
        t.check(heights[i] == h, "height at (%r, %r): %r, C++ API %r" % (px, pz, heights[i], h))

    # Normals and velocities: the velocity output on one thread, as the reference's serial runner.
    options, fast = SimulatorOptions(), ctypes.c_void_p()
    lib.ocean_simulator_options_init(ctypes.byref(options))
    t.check(options.struct_size == ctypes.sizeof(SimulatorOptions) and options.backend == b"cpu"
            and options.outputs == OUTPUT_DEFAULT, "simulator options defaults")
    options.outputs, options.threads = OUTPUT_DEFAULT | OUTPUT_VELOCITY, 1
    t.ok(lib.ocean_simulator_create_with_options(config, ctypes.byref(options),
                                                 ctypes.byref(fast)), "create_with_options")
    t.ok(lib.ocean_simulator_step(fast, ref["time"]), "step with velocity")
    m = len(ref["surface"])
    t.check(m > 0, "the reference has surface samples")
    sx = doubles([p[0] for p in ref["surface"]])
    sz = doubles([p[1] for p in ref["surface"]])
    normals, velocities = (ctypes.c_double * (3 * m))(), (ctypes.c_double * (3 * m))()
    t.ok(lib.ocean_simulator_normals(fast, sx, sz, m, normals), "normals")
    t.ok(lib.ocean_simulator_velocities(fast, sx, sz, m, velocities), "velocities")
    for i, p in enumerate(ref["surface"]):
        t.check(tuple(normals[3 * i:3 * i + 3]) == p[3:6],
                "normal at (%r, %r): %r, C++ API %r" % (p[0], p[1], normals[3 * i:3 * i + 3],
                                                        p[3:6]))
        t.check(tuple(velocities[3 * i:3 * i + 3]) == p[6:9],
                "velocity at (%r, %r): %r, C++ API %r" % (p[0], p[1],
                                                          velocities[3 * i:3 * i + 3], p[6:9]))
    t.error(lib.ocean_simulator_velocities(sim, sx, sz, m, velocities), UNSUPPORTED,
            "does not compute the velocity", "velocities without the velocity output")
    options.struct_size = 4
    t.error(lib.ocean_simulator_create_with_options(config, ctypes.byref(options),
                                                    ctypes.byref(ctypes.c_void_p())),
            INVALID_ARGUMENT, "options->struct_size = 4 is too small", "struct_size too small")
    lib.ocean_simulator_destroy(fast)

    params = SpectrumParams()
    lib.ocean_spectrum_params_init(ctypes.byref(params))
    t.check(math.isnan(params.hs_m) and params.model == b"jonswap", "spectrum params defaults")
    for model, hs, tp, omega, expected in ref["spectrum"]:
        params.model, params.hs_m, params.tp_s = model.encode(), hs, tp
        out = (ctypes.c_double * 1)()
        t.ok(lib.ocean_spectrum_evaluate(ctypes.byref(params), doubles([omega]), 1, out),
             "spectrum")
        t.check(out[0] == expected, "S(%r) = %r, C++ API %r" % (omega, out[0], expected))

    # Error paths: a status and the one-line message, never a crash.
    t.error(lib.ocean_config_merge_preset(config, b"no-such-preset"), INVALID_ARGUMENT,
            "--preset = no-such-preset is neither a file nor a preset", "bad preset name")
    t.error(lib.ocean_config_set(config, b"sea.no_such_key=1"), INVALID_ARGUMENT,
            "sea.no_such_key: unknown key", "bad key")
    t.error(lib.ocean_simulator_step(None, 0.0), INVALID_ARGUMENT,
            "ocean_simulator_step: simulator is NULL", "null handle")
    t.error(lib.ocean_simulator_step(sim, float("nan")), INVALID_ARGUMENT,
            "time_s = nan is out of range: must be a finite number", "NaN time")
    t.error(lib.ocean_simulator_heights(sim, doubles([float("nan")]), doubles([0.0]), 1, heights),
            INVALID_ARGUMENT, "x[0] = nan", "NaN position")
    t.error(lib.ocean_simulator_create(config, b"cuda", ctypes.byref(ctypes.c_void_p())),
            UNSUPPORTED, "CUDA", "backend not built in, or no CUDA device")
    t.ok(lib.ocean_simulator_step(sim, 2.0), "step after errors")
    t.check(t.message() == "", "a success clears the message")

    lib.ocean_simulator_destroy(sim)
    lib.ocean_config_destroy(config)
    if t.failures:
        print("capi_ctypes_test: %d check(s) failed" % t.failures, file=sys.stderr)
    return 1 if t.failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
