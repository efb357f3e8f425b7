// ocean.Simulator: configure, step, kick/wait, each frame's fields as numpy views, and batched
// height queries with the GIL released.
//
// Views and their lifetime. A field array is a read-only numpy view of the simulator's frame
// buffer (no copy), except `height`, a strided view of the displacement's h column (no copy
// either). Every array of one fields() call shares one FrameView base object that keeps the
// simulator alive, so an array never outlives the memory it points into. The Simulator double-
// buffers: the frame published by step k is the buffer step k + 2 writes. When a step (or kick,
// or reconfigure) is about to write a buffer that some array still views, the buffer is handed
// to its views (Simulator::detach: the arrays keep their memory, the simulator continues in a
// copy), so a held array never changes, never dangles and never blocks a step. The cost is one
// frame's copy per step while views of that buffer are alive; arrays no longer referenced (and
// collected) cost nothing.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "integers.hpp"
#include "ocean/backends.hpp"
#include "ocean/plan.hpp"
#include "ocean/task_runner.hpp"

namespace py = pybind11;

namespace ocean::python {
namespace {

class FrameView;

// The simulator and the live views of each of its frame buffers, shared with the views.
struct SimulatorState {
  std::unique_ptr<Simulator> sim;
  std::shared_mutex mutex;  // exclusive: step, kick, wait, reconfigure; shared: reads and queries
  std::mutex views_mutex;   // guards `views` and every view's frame and holder
  std::vector<FrameView*> views;

  void add(FrameView* v) {
    const std::lock_guard lock(views_mutex);
    views.push_back(v);
  }
  void remove(FrameView* v) {
    const std::lock_guard lock(views_mutex);
    std::erase(views, v);
  }
  // With the exclusive lock held: gives `buffer` to the views that show it, if any.
  void detach_if_viewed(const Frame& buffer);
};

// The base object of every field array: holds the simulator, and the frame's arrays once the
// simulator has handed them over (detach_if_viewed).
class FrameView {
 public:
  FrameView(std::shared_ptr<SimulatorState> state, const Frame* frame)
      : state_(std::move(state)), frame_(frame) {
    state_->add(this);
  }
  ~FrameView() { state_->remove(this); }
  FrameView(const FrameView&) = delete;
  FrameView& operator=(const FrameView&) = delete;

 private:
  friend struct SimulatorState;
  std::shared_ptr<SimulatorState> state_;
  const Frame* frame_;                   // the simulator's buffer, or *owned_ once handed over
  std::shared_ptr<const Frame> owned_;  // the handed-over buffer, shared by its views
};

void SimulatorState::detach_if_viewed(const Frame& buffer) {
  const std::lock_guard lock(views_mutex);
  if (std::none_of(views.begin(), views.end(), [&](FrameView* v) { return v->frame_ == &buffer; }))
    return;
  auto owned = std::make_shared<const Frame>(sim->detach(buffer));
  for (FrameView* v : views) {
    if (v->frame_ != &buffer) continue;
    v->frame_ = owned.get();
    v->owned_ = owned;
  }
}

class PySimulator {
 public:
  PySimulator(const SimulationConfig& config, const std::string& backend, int threads)
      : state_(std::make_shared<SimulatorState>()) {
    std::shared_ptr<TaskRunner> runner = make_tbb_runner(threads);
    state_->sim = take(make_simulator(config, backend, std::move(runner)));
  }

  void step(double time_s) { advance(time_s, false); }
  void kick(double time_s) { advance(time_s, true); }
  void wait() {
    const py::gil_scoped_release release;
    const std::unique_lock lock(state_->mutex);
    state_->sim->wait();
  }
  void reconfigure(const SimulationConfig& config) {
    Status s;
    {
      const py::gil_scoped_release release;
      const std::unique_lock lock(state_->mutex);
      state_->sim->wait();
      state_->detach_if_viewed(state_->sim->frame());
      state_->detach_if_viewed(state_->sim->back_buffer());
      s = state_->sim->reconfigure(config);
    }
    check(s);
  }

  // The arrays of one cascade of the published frame, views sharing one FrameView base.
  py::dict fields(const Integer& cascade) {
    const std::shared_lock lock(state_->mutex);
    const Frame& f = state_->sim->frame();
    const params::NumberOption<double> option{
        .flag = "cascade", .lo = 0, .hi = static_cast<double>(f.cascades.size()) - 1};
    const CascadeFrame& c = f.cascades[static_cast<std::size_t>(in_range(cascade, option))];
    const py::object base =
        py::cast(new FrameView(state_, &f), py::return_value_policy::take_ownership);
    const auto n = static_cast<py::ssize_t>(c.resolution);
    py::dict out;
    const auto view = [&](auto* data, std::vector<py::ssize_t> shape,
                          std::vector<py::ssize_t> strides, const py::dtype& dtype) {
      py::array a(dtype, std::move(shape), std::move(strides), data, base);
      py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
      return a;
    };
    const py::ssize_t f4 = sizeof(float);
    out["displacement"] =
        view(c.displacement.data(), {n, n, 3}, {n * 3 * f4, 3 * f4, f4}, py::dtype::of<float>());
    out["height"] =
        view(c.displacement.data() + 1, {n, n}, {n * 3 * f4, 3 * f4}, py::dtype::of<float>());
    out["displacement_half"] =
        view(c.displacement_half.data(), {n, n, 4}, {n * 8, 8, 2}, py::dtype("float16"));
    if (!c.normal.empty())
      out["normal"] =
          view(c.normal.data(), {n, n, 3}, {n * 3 * f4, 3 * f4, f4}, py::dtype::of<float>());
    if (!c.jacobian.empty())
      out["jacobian"] = view(c.jacobian.data(), {n, n}, {n * f4, f4}, py::dtype::of<float>());
    if (!c.foam.empty())
      out["foam"] = view(c.foam.data(), {n, n}, {n * f4, f4}, py::dtype::of<float>());
    out["packed"] =
        view(c.packed_mips.data(), {n, n, 4}, {n * 4, 4, 1}, py::dtype::of<std::uint8_t>());
    return out;
  }

  // Heights of the rendered surface above world (x, z) points, (n, 2) in, GIL released.
  py::object heights(const DoubleArray& xz, bool full) const {
    const std::vector<std::array<double, 2>> points = points_of(xz);
    const std::size_t n = points.size();
    std::vector<HeightSample> samples(n);
    {
      const py::gil_scoped_release release;
      const std::shared_lock lock(state_->mutex);
      state_->sim->heights_at(points, samples);
    }
    const auto count = static_cast<py::ssize_t>(n);
    py::array_t<double> h(count);
    for (std::size_t i = 0; i < n; ++i) h.mutable_data()[i] = samples[i].height_m;
    if (!full) return h;
    py::array_t<double> d({count, py::ssize_t{3}});
    py::array_t<double> src({count, py::ssize_t{2}});
    py::array_t<int> it(count);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < 3; ++j) d.mutable_data()[3 * i + j] = samples[i].displacement[j];
      for (std::size_t j = 0; j < 2; ++j) src.mutable_data()[2 * i + j] = samples[i].source_xz[j];
      it.mutable_data()[i] = samples[i].iterations;
    }
    py::dict out;
    out["height"] = h;
    out["displacement"] = d;
    out["source_xz"] = src;
    out["iterations"] = it;
    return out;
  }

  // Displacement (Dx, h, Dz) at undisplaced (x, z) points: Simulator::displacement_at, batched.
  py::array_t<double> displacements(const DoubleArray& xz) const {
    const std::vector<std::array<double, 2>> points = points_of(xz);
    const auto count = static_cast<py::ssize_t>(points.size());
    py::array_t<double> d({count, py::ssize_t{3}});
    double* out = d.mutable_data();
    {
      const py::gil_scoped_release release;
      const std::shared_lock lock(state_->mutex);
      for (std::size_t i = 0; i < points.size(); ++i) {
        const std::array<double, 3> v = state_->sim->displacement_at(points[i][0], points[i][1]);
        for (std::size_t j = 0; j < 3; ++j) out[3 * i + j] = v[j];
      }
    }
    return d;
  }

  // Height, normal and particle velocity above world (x, z) points: Simulator::surface_at.
  py::dict surface(const DoubleArray& xz) const {
    const std::vector<std::array<double, 2>> points = points_of(xz);
    const std::size_t n = points.size();
    std::vector<SurfaceSample> samples(n);
    {
      const py::gil_scoped_release release;
      const std::shared_lock lock(state_->mutex);
      state_->sim->surface_at(points, samples);
    }
    const auto count = static_cast<py::ssize_t>(n);
    py::array_t<double> h(count);
    py::array_t<double> normal({count, py::ssize_t{3}});
    py::array_t<double> velocity({count, py::ssize_t{3}});
    for (std::size_t i = 0; i < n; ++i) {
      h.mutable_data()[i] = samples[i].height_m;
      for (std::size_t j = 0; j < 3; ++j) {
        normal.mutable_data()[3 * i + j] = samples[i].normal[j];
        velocity.mutable_data()[3 * i + j] = samples[i].velocity[j];
      }
    }
    py::dict out;
    out["height"] = h;
    out["normal"] = normal;
    out["velocity"] = velocity;
    return out;
  }

  [[nodiscard]] std::vector<double> foam_weights() const {
    const std::shared_lock lock(state_->mutex);
    return state_->sim->plan().foam().weights;
  }

  [[nodiscard]] double time() const {
    const std::shared_lock lock(state_->mutex);
    return state_->sim->frame().time_s;
  }
  [[nodiscard]] std::uint64_t frame_index() const {
    const std::shared_lock lock(state_->mutex);
    return state_->sim->frame().index;
  }
  [[nodiscard]] const SimulationConfig& config() const { return state_->sim->config(); }
  [[nodiscard]] std::string backend() const { return std::string(state_->sim->backend().name()); }

 private:
  // An (n, 2) array of finite world (x, z) points as the library's point list.
  static std::vector<std::array<double, 2>> points_of(const DoubleArray& xz) {
    if (xz.ndim() != 2 || xz.shape(1) != 2) {
      std::string shape;
      for (py::ssize_t i = 0; i < xz.ndim(); ++i)
        shape += (i ? ", " : "") + std::to_string(xz.shape(i));
      raise(invalid_argument("xz must be an (n, 2) array of world (x, z) points, m; got shape (" +
                             shape + ")"));
    }
    const auto n = static_cast<std::size_t>(xz.shape(0));
    std::vector<std::array<double, 2>> points(n);
    for (std::size_t i = 0; i < n; ++i) points[i] = {xz.data()[2 * i], xz.data()[2 * i + 1]};
    for (const auto& p : points) {
      check(require_finite("x", p[0]));
      check(require_finite("z", p[1]));
    }
    return points;
  }

  // Steps (kick = in the background) after publishing any kicked frame; a back buffer that is
  // still viewed goes to its views first.
  void advance(double time_s, bool kick) {
    check(require_finite("time_s", time_s));
    const py::gil_scoped_release release;
    const std::unique_lock lock(state_->mutex);
    state_->sim->wait();
    state_->detach_if_viewed(state_->sim->back_buffer());
    kick ? state_->sim->kick(time_s) : state_->sim->step(time_s);
  }

  std::shared_ptr<SimulatorState> state_;
};

}  // namespace

void bind_simulator(py::module_& m) {
  py::class_<FrameView>(m, "FrameView",
                        "The base object of field arrays: keeps the simulator alive, and its "
                        "frame's memory once a step has moved on from it.");
  py::class_<PySimulator>(m, "Simulator",
                          "A simulation of the preset's sea on a backend ('cpu', 'vulkan').\n\n"
                          "Its fields are read-only numpy views that stay valid across steps "
                          "(docs/python.md, \"Field views and their lifetime\").")
      .def(py::init(
               [](const py::object& preset, const std::string& backend, const Integer& threads) {
                 const auto n = static_cast<int>(in_range(threads, kThreads));
                 return std::make_unique<PySimulator>(config_of(preset), backend, n);
               }),
           py::arg("preset") = py::none(), py::kw_only(), py::arg("backend") = "cpu",
           py::arg("threads") = 0,
           R"doc(A simulator of the preset's sea.

Parameters
----------
preset : Preset, str or None, optional
    An ocean.Preset, a built-in name (calm, moderate, storm) or a preset file; None: the
    defaults.
backend : str, optional
    'cpu' (default) or 'vulkan'.
threads : int, optional
    oneTBB threads of the CPU backend, 0 (every hardware thread) to 256.)doc")
      .def("step", &PySimulator::step, py::arg("time_s"),
           R"doc(Computes and publishes the frame at time_s (the GIL released meanwhile).

Parameters
----------
time_s : float
    Simulation time, s, finite.)doc")
      .def("kick", &PySimulator::kick, py::arg("time_s"),
           R"doc(Starts the frame at time_s in the background; the published frame stays readable.

Parameters
----------
time_s : float
    Simulation time, s, finite. ``wait()`` publishes the frame.)doc")
      .def("wait", &PySimulator::wait, "Waits for the kicked frame and publishes it.")
      .def(
          "reconfigure",
          [](PySimulator& s, const py::object& preset) { s.reconfigure(config_of(preset)); },
          py::arg("preset"), R"doc(Regenerates spectra and buffers for a new configuration.

Parameters
----------
preset : Preset, str or None
    An ocean.Preset, a built-in name or a preset file; None: the defaults.)doc")
      .def("fields", &PySimulator::fields, py::arg("cascade") = 0,
           R"doc(The published frame's arrays of one cascade, read-only numpy views [row][col].

Parameters
----------
cascade : int, optional
    The cascade, 0 (the longest waves) to len(patch_sizes) - 1.

Returns
-------
dict of str to numpy.ndarray
    displacement (N, N, 3) float32 (Dx, h, Dz), m; height (N, N), a strided view of it;
    displacement_half (N, N, 4) float16; normal (N, N, 3), jacobian (N, N) and foam (N, N)
    where the configuration's outputs ask for them; packed (N, N, 4) uint8, RGBA mip 0. The
    views stay valid, and unchanged, after later steps.)doc")
      .def("heights", &PySimulator::heights, py::arg("xz"), py::kw_only(), py::arg("full") = false,
           R"doc(Heights of the surface above world points (the GIL released meanwhile).

Parameters
----------
xz : array_like of float, shape (n, 2)
    World positions (x, z), m.
full : bool, optional
    Also return where each height comes from.

Returns
-------
numpy.ndarray of float, shape (n,) or dict
    The heights above the mean level, m; with full=True a dict of height (n,), displacement
    (n, 3), source_xz (n, 2) (the undisplaced point that lands at each position) and
    iterations (n,).)doc")
      .def("displacements", &PySimulator::displacements, py::arg("xz"),
           R"doc(Displacements of undisplaced points (the GIL released meanwhile).

The point that starts at (x, z) is drawn at (x + Dx, h, z + Dz): each cascade's maps sampled
bilinearly with wrap addressing, as a GPU samples them, and summed (docs/math.md M.7.6).

Parameters
----------
xz : array_like of float, shape (n, 2)
    Undisplaced world positions (x, z), m.

Returns
-------
numpy.ndarray of float, shape (n, 3)
    (Dx, h, Dz) at each point, m.)doc")
      .def("surface", &PySimulator::surface, py::arg("xz"),
           R"doc(The surface above world points: height, normal and particle velocity.

Parameters
----------
xz : array_like of float, shape (n, 2)
    World positions (x, z), m.

Returns
-------
dict of str to numpy.ndarray
    height (n,), m, as ``heights`` returns it; normal (n, 3), the unit normal (nx, ny, nz)
    of the displaced surface, y up (docs/math.md M.7.11); velocity (n, 3), m/s, of the water
    particle at the surface (u, w, v), NaN unless the preset's outputs ask for velocity.)doc")
      .def_property_readonly("foam_weights", &PySimulator::foam_weights,
                             "Each cascade's weight in the foam coverage sum_c w_c*foam_c of the "
                             "breaking foam source (docs/rendering.md R.11); empty for the ramp "
                             "source, whose cascades' foam is united.")
      .def_property_readonly("time", &PySimulator::time, "Time of the published frame, s.")
      .def_property_readonly("frame_index", &PySimulator::frame_index,
                             "Frames computed since the configuration: 1 after the first step.")
      .def_property_readonly("backend", &PySimulator::backend, "The backend's name, e.g. 'cpu'.")
      .def_property_readonly(
          "resolution", [](const PySimulator& s) { return s.config().resolution; },
          "Texels per side N of every cascade.")
      .def_property_readonly(
          "patch_sizes", [](const PySimulator& s) { return s.config().cascade_patch_sizes_m; },
          "Each cascade's patch side, m, longest first.")
      .def_property_readonly(
          "loop_period_s", [](const PySimulator& s) { return s.config().loop_period_s; },
          "The period after which the sea repeats exactly, s; 0: it never does.");
}

}  // namespace ocean::python
