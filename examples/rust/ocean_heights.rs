// The C ABI (include/ocean/ocean.h, libocean_c.so) from Rust, with the standard library only: a
// small safe wrapper (handles freed on drop, statuses turned into Result with the library's own
// message) and a program that repeats a scenario written by the C++ API and compares the numbers.
//
// Build (tests/capi/CMakeLists.txt does this with Debian's rustc):
//   rustc --edition 2021 -O -L <dir of libocean_c.so> -l dylib=ocean_c ocean_heights.rs
// Run:   ocean_heights REFERENCE.txt   (capi_reference's file: preset, sets, time, heights,
//        spectra); prints what it checked and exits 0 when every number is the same double.
use std::ffi::{CStr, CString};
use std::os::raw::c_char;

#[repr(C)]
struct RawConfig {
    _private: [u8; 0],
}
#[repr(C)]
struct RawSimulator {
    _private: [u8; 0],
}

/// ocean_spectrum_params, field for field.
#[repr(C)]
struct SpectrumParams {
    struct_size: usize,
    model: *const c_char,
    hs_m: f64,
    tp_s: f64,
    wind_speed_mps: f64,
    fetch_m: f64,
    gamma: f64,
    depth_m: f64,
    gravity_mps2: f64,
}

const OCEAN_OK: i32 = 0;
const OCEAN_INVALID_ARGUMENT: i32 = 1;

extern "C" {
    fn ocean_version_string() -> *const c_char;
    fn ocean_last_error() -> *const c_char;
    fn ocean_config_create(out: *mut *mut RawConfig) -> i32;
    fn ocean_config_destroy(config: *mut RawConfig);
    fn ocean_config_merge_preset(config: *mut RawConfig, name_or_path: *const c_char) -> i32;
    fn ocean_config_set(config: *mut RawConfig, assignment: *const c_char) -> i32;
    fn ocean_simulator_create(
        config: *const RawConfig,
        backend: *const c_char,
        out: *mut *mut RawSimulator,
    ) -> i32;
    fn ocean_simulator_destroy(simulator: *mut RawSimulator);
    fn ocean_simulator_step(simulator: *mut RawSimulator, time_s: f64) -> i32;
    fn ocean_simulator_heights(
        simulator: *const RawSimulator,
        x: *const f64,
        z: *const f64,
        count: usize,
        heights: *mut f64,
    ) -> i32;
    fn ocean_spectrum_params_init(params: *mut SpectrumParams);
    fn ocean_spectrum_evaluate(
        params: *const SpectrumParams,
        omega: *const f64,
        count: usize,
        spectrum: *mut f64,
    ) -> i32;
}

/// A failed call: its status and the library's one-line message.
#[derive(Debug)]
struct Error {
    status: i32,
    message: String,
}

fn check(status: i32) -> Result<(), Error> {
    if status == OCEAN_OK {
        return Ok(());
    }
    // SAFETY: ocean_last_error never returns NULL; the text lives until this thread's next call.
    let message = unsafe { CStr::from_ptr(ocean_last_error()) }.to_string_lossy().into_owned();
    Err(Error { status, message })
}

fn text(s: &str) -> CString {
    CString::new(s).expect("no NUL inside")
}

struct Config(*mut RawConfig);

impl Config {
    fn new() -> Result<Config, Error> {
        let mut raw = std::ptr::null_mut();
        check(unsafe { ocean_config_create(&mut raw) })?;
        Ok(Config(raw))
    }
    fn merge_preset(&mut self, name: &str) -> Result<(), Error> {
        check(unsafe { ocean_config_merge_preset(self.0, text(name).as_ptr()) })
    }
    fn set(&mut self, assignment: &str) -> Result<(), Error> {
        check(unsafe { ocean_config_set(self.0, text(assignment).as_ptr()) })
    }
}

impl Drop for Config {
    fn drop(&mut self) {
        unsafe { ocean_config_destroy(self.0) }
    }
}

struct Simulator(*mut RawSimulator);

impl Simulator {
    fn new(config: &Config, backend: &str) -> Result<Simulator, Error> {
        let mut raw = std::ptr::null_mut();
        check(unsafe { ocean_simulator_create(config.0, text(backend).as_ptr(), &mut raw) })?;
        Ok(Simulator(raw))
    }
    fn step(&mut self, time_s: f64) -> Result<(), Error> {
        check(unsafe { ocean_simulator_step(self.0, time_s) })
    }
    fn heights(&self, x: &[f64], z: &[f64]) -> Result<Vec<f64>, Error> {
        assert_eq!(x.len(), z.len());
        let mut h = vec![0.0; x.len()];
        check(unsafe {
            ocean_simulator_heights(self.0, x.as_ptr(), z.as_ptr(), x.len(), h.as_mut_ptr())
        })?;
        Ok(h)
    }
}

impl Drop for Simulator {
    fn drop(&mut self) {
        unsafe { ocean_simulator_destroy(self.0) }
    }
}

fn spectrum(model: &str, hs_m: f64, tp_s: f64, omega: &[f64]) -> Result<Vec<f64>, Error> {
    let model = text(model);
    let mut params = SpectrumParams {
        struct_size: 0,
        model: std::ptr::null(),
        hs_m: 0.0,
        tp_s: 0.0,
        wind_speed_mps: 0.0,
        fetch_m: 0.0,
        gamma: 0.0,
        depth_m: 0.0,
        gravity_mps2: 0.0,
    };
    unsafe { ocean_spectrum_params_init(&mut params) };
    params.model = model.as_ptr();
    params.hs_m = hs_m;
    params.tp_s = tp_s;
    let mut s = vec![0.0; omega.len()];
    check(unsafe { ocean_spectrum_evaluate(&params, omega.as_ptr(), omega.len(), s.as_mut_ptr()) })?;
    Ok(s)
}

fn numbers(fields: &[&str]) -> Vec<f64> {
    fields.iter().map(|f| f.parse::<f64>().expect("a number")).collect()
}

fn run(reference: &str) -> Result<usize, String> {
    let content = std::fs::read_to_string(reference).map_err(|e| format!("{}: {}", reference, e))?;
    let mut config = Config::new().map_err(|e| e.message)?;
    let (mut time_s, mut xs, mut zs, mut expected) = (0.0, Vec::new(), Vec::new(), Vec::new());
    let mut spectra = Vec::new();
    for line in content.lines() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        match fields.first().copied() {
            Some("preset") => config.merge_preset(fields[1]).map_err(|e| e.message)?,
            Some("set") => config.set(fields[1]).map_err(|e| e.message)?,
            Some("time") => time_s = numbers(&fields[1..2])[0],
            Some("height") => {
                let v = numbers(&fields[1..4]);
                xs.push(v[0]);
                zs.push(v[1]);
                expected.push(v[2]);
            }
            Some("spectrum") => spectra.push((fields[1].to_string(), numbers(&fields[2..6]))),
            _ => {}
        }
    }
    if expected.is_empty() || spectra.is_empty() {
        return Err(format!("{}: no height or spectrum lines", reference));
    }
    let mut sim = Simulator::new(&config, "cpu").map_err(|e| e.message)?;
    sim.step(time_s).map_err(|e| e.message)?;
    let heights = sim.heights(&xs, &zs).map_err(|e| e.message)?;
    for i in 0..heights.len() {
        if heights[i] != expected[i] {
            return Err(format!(
                "height at ({}, {}): {} through the C ABI, {} through C++",
                xs[i], zs[i], heights[i], expected[i]
            ));
        }
    }
    for (model, v) in &spectra {
        let s = spectrum(model, v[0], v[1], &v[2..3]).map_err(|e| e.message)?;
        if s[0] != v[3] {
            return Err(format!("{} S({}) = {} through the C ABI, {} through C++", model, v[2], s[0], v[3]));
        }
    }
    // A bad value: the status and the library's own one-line message.
    match config.set("resolution=-3") {
        Err(Error { status: OCEAN_INVALID_ARGUMENT, message }) if message.contains("resolution") => {
            println!("refused as expected: {}", message)
        }
        other => return Err(format!("resolution=-3 gave {:?}", other)),
    }
    Ok(heights.len() + spectra.len())
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 2 {
        eprintln!("usage: ocean_heights REFERENCE.txt");
        std::process::exit(2);
    }
    let version = unsafe { CStr::from_ptr(ocean_version_string()) }.to_string_lossy().into_owned();
    match run(&args[1]) {
        Ok(n) => println!("ocean {} from Rust: {} heights and spectra equal to the C++ API's", version, n),
        Err(message) => {
            eprintln!("ocean_heights: {}", message);
            std::process::exit(1);
        }
    }
}
