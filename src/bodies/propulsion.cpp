// Propulsion of a floating body: a horizontal thrust along its heading at a stated point, driven
// by a speed loop, and a steering moment about the vertical driven by a heading loop. Equations
// (B.8)–(B.10): docs/bodies.md.
//
// This work is based on:
//   T. I. Fossen, "Handbook of Marine Craft Hydrodynamics and Motion Control", Wiley 2011 — the
//   surge resistance of a hull as linear plus quadratic damping in the speed, X_u·u +
//   X_|u|u·|u|·u (what B.4 integrates to for a moving hull, B.9), and PID speed and heading
//   autopilots with integral action against a constant resistance.
//   K. J. Åström, R. M. Murray, "Feedback Systems", Princeton 2008, §10.4 — integrator windup
//   while the actuator saturates; here cured by conditional integration (the integral frozen
//   while the thrust is at a limit and the error pushes further into it).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "body_math.hpp"
#include "ocean/bodies.hpp"

namespace ocean::bodies {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// An angle in (−π, π].
double wrap(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

}  // namespace

Status validate(const PropulsionParams& p) {
  if (Status s = require_positive("propulsion max_thrust_n", p.max_thrust_n); !s.ok()) return s;
  for (double v : p.thrust_point_m)
    if (!std::isfinite(v)) return invalid_argument("propulsion thrust_point_m is not finite");
  if (Status s = require_positive("propulsion speed_time_s", p.speed_time_s); !s.ok()) return s;
  if (Status s = require_positive("propulsion max_yaw_moment_nm", p.max_yaw_moment_nm); !s.ok())
    return s;
  return require_positive("propulsion heading_time_s", p.heading_time_s);
}

Status validate(const HelmCommand& c) {
  if (Status s = require_non_negative("helm speed_mps", c.speed_mps); !s.ok()) return s;
  if (Status s = require_finite("helm heading_deg", c.heading_deg); !s.ok()) return s;
  return require_finite("helm turn_rate_degps", c.turn_rate_degps);
}

void Propulsion::reset(double speed_mps) {
  integral_mps_s_ = 2.0 * params_.speed_time_s * speed_mps;
  heading_integral_rad_s_ = 0.0;
}

Result<Propulsion> Propulsion::make(const PropulsionParams& params) {
  if (Status s = validate(params); !s.ok()) return s;
  Propulsion p;
  p.params_ = params;
  return p;
}

Result<Wrench> Propulsion::control(const FloatingBody& body, const HelmCommand& command,
                                   double dt_s) {
  if (Status s = validate(command); !s.ok()) return s;
  if (Status s = require_positive("dt_s", dt_s); !s.ok()) return s;
  const BodyState& state = body.state();
  const Mat3 r = rotation(state.orientation);
  // (B.8) The heading: the body's +x on the horizontal.
  const Vec3 forward = mul(r, Vec3{1.0, 0.0, 0.0});
  const double horizontal = std::hypot(forward[0], forward[2]);
  Wrench out;
  thrust_n_ = 0.0;
  yaw_moment_nm_ = 0.0;
  if (!(horizontal > 1e-6)) return out;  // standing on its bow: no thrust, no steering
  const Vec3 along{forward[0] / horizontal, 0.0, forward[2] / horizontal};

  // (B.9) Speed loop: the drag of the last step along the heading compensated, then PI with
  // gains m·2/τ and m/τ², the proportional part on the speed alone (set-point weight 0), which
  // leaves a critically damped pair of poles at −1/τ whatever the hull's resistance and follows a
  // new command without overshoot; the integral takes the rest (the pressure's surge force in
  // waves). Thrust in [0, T_max]; the integral is frozen while the thrust saturates in the
  // direction the error pushes (conditional integration).
  const double m = body.params().mass_kg, tau = params_.speed_time_s;
  const double resistance = -dot(body.forces().drag_n, along);
  const double u = dot(state.velocity_mps, along);
  const double error = command.speed_mps - u;
  const double integral = integral_mps_s_ + error * dt_s;
  const double wanted = resistance + m * (-2.0 * u / tau + integral / (tau * tau));
  const bool winding =
      (wanted > params_.max_thrust_n && error > 0.0) || (wanted < 0.0 && error < 0.0);
  if (!winding) integral_mps_s_ = integral;
  thrust_n_ = std::clamp(wanted, 0.0, params_.max_thrust_n);
  out.force_n = scale(along, thrust_n_);
  out.torque_nm = cross(mul(r, params_.thrust_point_m), out.force_n);

  // (B.10) Heading loop, PID with gains I_ψ·3/τ², I_ψ·3/τ and I_ψ/τ³ on the errors of ψ, ψ̇ and
  // ∫ψ (a triple pole at −1/τ for a bare yaw inertia; the integral holds the course against a
  // steady yaw moment of the waves or the hull's yaw drag on a turn): ψ̈ = N/I_ψ, the yaw rate
  // ψ̇ = −ω_y (a heading turns +x towards +z, a rotation about −y), N clamped to ±N_max, the
  // integral frozen while N saturates in the direction the error pushes.
  const Mat3 inertia_world = mul(mul(r, body.params().inertia_kgm2), transpose(r));
  const double i_yaw = inertia_world[4], tau_psi = params_.heading_time_s;
  const double heading_error = wrap(command.heading_deg * kDegree - std::atan2(along[2], along[0]));
  const double rate_error = command.turn_rate_degps * kDegree + state.angular_velocity_radps[1];
  const double heading_integral = heading_integral_rad_s_ + heading_error * dt_s;
  const double moment =
      i_yaw * (3.0 * heading_error / (tau_psi * tau_psi) + 3.0 * rate_error / tau_psi +
               heading_integral / (tau_psi * tau_psi * tau_psi));
  const bool yaw_winding = (moment > params_.max_yaw_moment_nm && heading_error > 0.0) ||
                           (moment < -params_.max_yaw_moment_nm && heading_error < 0.0);
  if (!yaw_winding) heading_integral_rad_s_ = heading_integral;
  yaw_moment_nm_ = std::clamp(moment, -params_.max_yaw_moment_nm, params_.max_yaw_moment_nm);
  out.torque_nm[1] -= yaw_moment_nm_;
  return out;
}

}  // namespace ocean::bodies
