// The far field's noise map in a configured CUDA simulation (docs/rendering.md R.13a): its stream
// and join event beside the cascades', its kernel's arguments, the per-frame parameters written
// into pinned memory, the operations of plan.hpp's schedule that belong to it, and its readback
// into Frame::far_noise. Every function is a no-op where the layout has no map.
#pragma once

#include "device_state.hpp"
#include "ocean/far_noise.hpp"

namespace ocean::cuda::detail {

/// After create_device_state: the map's stream (index noise_stream(layout)), its join event
/// (noise_event(layout)) and DeviceState::noise, pointing into the state's allocations.
Status create_noise_state(DeviceState& state);

/// The map's parameters at time_s (far_noise_map::params: each octave's drifted lattice
/// coordinate split in double precision) into pinned memory, where the frame's noise_params
/// operation copies them from. Call while no frame is in flight.
void write_noise_params(DeviceState& state, const FarFieldNoise& noise, const FarNoiseConfig& map,
                        double time_s);

/// Issues one of the map's operations (Op::noise_params, Op::noise, Op::noise_readback).
Status issue_noise_op(DeviceState& state, const Op& op, cudaStream_t stream);

/// The pinned copy of the map into out.far_noise (when the frame carries one). After the frame.
void read_noise_map(const DeviceState& state, Frame& out);

}  // namespace ocean::cuda::detail
