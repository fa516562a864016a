#pragma once
// Example systems with one flexible body (given code, modules 7 and 8). Every builder takes the
// formulation as a BodyFactory: make_intuitive_body (module 7, the default), make_ffrf_body
// (module 8) or make_modal_ffrf_body (the fast form of extras/fast_ffrf), and returns the
// model with consistent initial conditions at t = 0.

#include "fmbd/flexible_body.hpp"

namespace fmbd {

/// The reduction basis of an example's flexible body (module 6), which also chooses its frame:
/// free_free_modes: modal truncation, `modes` elastic ones, the frame at the centroid;
/// craig_bampton: the joint nodes as interface and `modes` fixed-interface modes, made FFRF-ready
///   (elastic size 3 x interface nodes - 3 + modes; M-orthogonal to the rigid motions, so the
///   frame is again the centroid's);
/// clamped_frame: the frame clamped at the first joint node, `modes` cantilever modes of that
///   node (clamped_frame_body_data).
enum class BodyBasis { free_free_modes, craig_bampton, clamped_frame };

struct FlexibleExample {
  Model model;
  VecX q0, qd0;                                ///< consistent at t = 0
  BodyId flexible;                             ///< the flexible body
  std::shared_ptr<const FlexibleBodyData> data;  ///< its data
};

/// The flexible body's elastic coordinates at t = 0, for every builder below: q_f and q_f_dot
/// (each empty, the default: zero; otherwise of the basis's size, data->num_modes()). The
/// builder then solves the constraints and the velocity equation for the frame coordinates of
/// every body (Newton iterations on the least-norm correction), keeping q_f and q_f_dot as given.
struct InitialElasticState {
  VecX q_f;
  VecX q_f_dot;
};

/// Free-free modes chosen by kind, for a straight beam (BodyBasis::free_free_modes): the lowest
/// `bending` modes whose motion is mostly across the beam and the lowest `axial` ones mostly along
/// it (a mode is axial when its axial DOFs carry most of its kinetic energy). Both negative (the
/// default): the lowest `modes` of any kind.
struct ModeSelection {
  int bending = -1;
  int axial = -1;
};

/// The basis of a straight beam along x with the rigid modes and the free-free modes that
/// `selection` asks for, in order of frequency (negative counts: none of that kind). Throws
/// std::invalid_argument if the mesh has fewer modes of a kind than asked.
ReducedBasis modes_by_kind(const FeModel& fe, const FeMatrices& m, const ModeSelection& selection);

/// A beam hinged at its end node 0 to the ground at the origin, horizontal along +x at the start,
/// released from rest under gravity g = (0, -9.81).
struct FlexiblePendulumParameters {
  double length = 1.0;       ///< [m]
  double side = 0.01;        ///< square section [m]
  double E = 210e9;          ///< [Pa]
  double rho = 7850.0;       ///< [kg/m^3]
  int elements = 10;
  int modes = 4;
  BodyBasis basis = BodyBasis::free_free_modes;
  MassMatrixType mass_type = MassMatrixType::lumped;
  double gravity = 9.81;     ///< [m/s^2], acting along -y
  ModeSelection selection;   ///< free_free_modes by kind, instead of `modes`
  InitialElasticState initial;
};
FlexibleExample flexible_pendulum(const FlexiblePendulumParameters& p = {},
                                  const BodyFactory& make_body = make_intuitive_body);

/// Slider-crank with a rigid crank driven at constant speed, a flexible connecting rod pinned to
/// the crank and to a rigid slider on the x axis. The crank starts at crank_angle (0: along +x,
/// top dead centre, everything on the x axis), the rod undeformed, with the velocities of the
/// rigid mechanism. Defaults: a 0.15 m crank, a 0.30 m steel rod with a 5 mm square section,
/// 150 rad/s, no gravity, as in the common flexible slider-crank benchmark.
struct FlexibleSliderCrankParameters {
  double crank_length = 0.15;  ///< [m]
  double crank_mass = 0.1;     ///< [kg]
  double crank_inertia = -1;   ///< about its centroid [kg m^2]; negative: a slender rod, m l^2 / 12
  double rod_length = 0.30;    ///< [m]
  double rod_side = 0.005;     ///< square section [m], unless rod_height is set
  double rod_height = 0.0;     ///< rectangular section b x h: h, in the plane of motion [m]
  double rod_width = 0.0;      ///< b, out of the plane [m]; 0: rod_side
  double E = 200e9;            ///< [Pa]
  double rho = 7870.0;         ///< [kg/m^3]
  double slider_mass = 0.03;   ///< [kg]
  double slider_inertia = -1;  ///< [kg m^2]; negative: a 20 mm square block, m s^2 / 6
  double crank_speed = 150.0;  ///< [rad/s], from t = 0
  double crank_angle = 0.0;    ///< at t = 0 [rad]
  double gravity = 0.0;        ///< [m/s^2], along -y
  int elements = 8;
  int modes = 2;
  BodyBasis basis = BodyBasis::craig_bampton;  ///< interface: both end nodes
  MassMatrixType mass_type = MassMatrixType::consistent;
  ModeSelection selection;  ///< free_free_modes by kind, instead of `modes`
  InitialElasticState initial;
};
/// Point names: "crank tip", "rod start" (node 0), "rod mid" (the node nearest mid-span, if any),
/// "rod end" (last node), "slider". Body names "crank", "rod", "slider".
FlexibleExample flexible_slider_crank(const FlexibleSliderCrankParameters& p = {},
                                      const BodyFactory& make_body = make_intuitive_body);

/// A beam clamped at node 0 to a hub at the origin whose angle follows the smooth spin-up
///   theta(t) = Omega/T (t^2/2 + (T/(2 pi))^2 (cos(2 pi t/T) - 1))   for t < T,
///   theta(t) = Omega (t - T/2)                                       after,
/// so that the spin rate rises from 0 to Omega in T seconds with zero angular acceleration at both
/// ends. No gravity. Defaults: an aluminium beam 8 m long (first cantilever frequency about
/// 2.9 rad/s), reduced by Craig-Bampton on its root node, which gives the cantilever modes.
struct SpinUpBeamParameters {
  double length = 8.0;      ///< [m]
  double A = 7.3e-5;        ///< [m^2]
  double I = 8.218e-9;      ///< [m^4]
  double E = 68.95e9;       ///< [Pa]
  double rho = 2766.67;     ///< [kg/m^3]
  double spin_rate = 2.0;   ///< Omega [rad/s]
  double spin_up_time = 15.0;  ///< T [s]
  int elements = 10;
  int modes = 3;
  BodyBasis basis = BodyBasis::craig_bampton;  ///< interface: the root node
  MassMatrixType mass_type = MassMatrixType::consistent;
  ModeSelection selection;  ///< free_free_modes by kind, instead of `modes`
  InitialElasticState initial;
};
FlexibleExample spin_up_beam(const SpinUpBeamParameters& p = {}, const BodyFactory& make_body = make_intuitive_body);

/// The spin-up profile above, as a drive function.
DriveFunction spin_up_profile(double spin_rate, double spin_up_time);

/// Global position of the flexible beam's neutral axis at distance s from its node 0, measured
/// along the undeformed beam (0 <= s <= its length); q of the whole model. Between two nodes it
/// interpolates with the element's own shape functions: linear along the element, cubic
/// Hermite across it (nodal displacement and rotation at both ends). At a node it is the node's
/// position. Throws std::invalid_argument for s outside the beam.
Vec2 beam_point(const FlexibleExample& ex, const VecX& q, double s);

/// Transverse deflection of the beam at s (as in beam_point) from the chord through its end
/// nodes, positive to the left of the chord.
double deflection_at(const FlexibleExample& ex, const VecX& q, double s);

/// deflection_at() at mid-span, s = length / 2: a node for an even number of elements,
/// otherwise the middle of the middle element.
double midspan_deflection(const FlexibleExample& ex, const VecX& q);

}  // namespace fmbd
