// The far field's noise map in a configured CUDA simulation (far_noise_state.hpp).
#include "far_noise_state.hpp"

#include <cassert>
#include <cstring>

#include "errors.hpp"
#include "sim/far_noise_map.hpp"

namespace ocean::cuda::detail {

Status create_noise_state(DeviceState& st) {
  const Layout& l = st.layout;
  if (l.noise_resolution == 0) return {};
  assert(st.streams.size() == static_cast<std::size_t>(noise_stream(l)));
  assert(st.events.size() == static_cast<std::size_t>(noise_event(l)));
  if (Status s =
          to_status(cudaStreamCreateWithFlags(&st.streams.emplace_back(), cudaStreamNonBlocking),
                    "cudaStreamCreate");
      !s.ok())
    return s;
  if (Status s =
          to_status(cudaEventCreateWithFlags(&st.events.emplace_back(), cudaEventDisableTiming),
                    "cudaEventCreate");
      !s.ok())
    return s;
  st.noise = {.params = reinterpret_cast<const noise::FarNoiseMapParams*>(
                  st.device + l.noise_params_device.offset),
              .map = reinterpret_cast<float*>(st.device + l.noise_map.offset),
              .resolution = l.noise_resolution};
  return {};
}

void write_noise_params(DeviceState& st, const FarFieldNoise& noise, const FarNoiseConfig& map,
                        double time_s) {
  if (st.layout.noise_resolution == 0) return;
  const noise::FarNoiseMapParams p = far_noise_map::params(noise, map, time_s);
  std::memcpy(st.host + st.layout.noise_params_host.offset, &p, sizeof(p));
}

Status issue_noise_op(DeviceState& st, const Op& op, cudaStream_t stream) {
  const Layout& l = st.layout;
  switch (op.kind) {
    case Op::noise_params:
      return to_status(cudaMemcpyAsync(st.device + l.noise_params_device.offset,
                                       st.host + l.noise_params_host.offset,
                                       l.noise_params_device.bytes, cudaMemcpyHostToDevice, stream),
                       "the noise map parameters' upload");
    case Op::noise: return to_status(launch_far_noise(st.noise, stream), "the noise map kernel");
    case Op::noise_readback:
      return to_status(
          cudaMemcpyAsync(st.host + l.noise_readback.offset, st.device + l.noise_map.offset,
                          l.noise_map.bytes, cudaMemcpyDeviceToHost, stream),
          "the noise map's readback copy");
    default: break;
  }
  return Status(ErrorCode::internal, "issue_noise_op: not an operation of the noise map");
}

void read_noise_map(const DeviceState& st, Frame& out) {
  const Layout& l = st.layout;
  if (l.noise_resolution == 0 || out.far_noise.height_slope.empty()) return;
  assert(out.far_noise.height_slope.size() * sizeof(float) == l.noise_readback.bytes);
  std::memcpy(out.far_noise.height_slope.data(), st.host + l.noise_readback.offset,
              l.noise_readback.bytes);
}

}  // namespace ocean::cuda::detail
