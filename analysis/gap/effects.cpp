#include "effects.h"

#include "sensor_response.h"

#include <cmath>
#include <cstdio>

namespace granpen {

std::string deck_number(double v)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

namespace {

// Bench contact law (shared/scenarios/bench.md); contact_stiffness scales it.
const double KN = 1e9, DT_POUR = 5e-6, DT_PUSH = 2e-6;
const double MOUNT_MASS = 100.0, MOUNT_ZETA = 0.2;    // g; damping ratio of the sensor mount

DeckVars none(double) { return {}; }
DeckVars rolling(double a) { return {{"mu_roll", deck_number(a)}}; }
DeckVars poly(double a) { return {{"poly", deck_number(a)}}; }
DeckVars walls(double a) { return {{"walls", "1"}, {"mu_wall", deck_number(a)}}; }
DeckVars stiffness(double a)
{
  // a = log10(k / k_bench); a Hertz contact's duration scales as k^(-2/5): the timestep too
  const double s = std::pow(10.0, a);
  const double dt = std::min(1.0, std::pow(s, -0.4));
  // keep the 1e-4 s trace window a whole number of steps
  const double push_steps = std::ceil(50.0 / dt);
  char pour[32], push[32];
  std::snprintf(pour, sizeof pour, "%.10g", DT_POUR * dt);
  std::snprintf(push, sizeof push, "%.10g", 1e-4 / push_steps);
  return {{"kn", deck_number(KN * s)}, {"kt", deck_number(KN * s)}, {"dt_pour", pour}, {"dt_push", push}};
}
// measurement_chain: a = the natural period of the sensor's mount, ms, with the rod's 100 g
// (fix rod/drive mount k c m: k = m (2 pi / T)^2, c = 2 zeta sqrt(k m)). The sensor reads
// k x + c x' of m x'' + c x' + k x = F: while the rod's motion does not feed back into the
// grains, that is the grains' force through the filter core/sensor_response.h (mount_filter).
// Measured against LAMMPS's own mount (bench/gap_mount_filter.sh, docs/gap.md): so up to
// 2 ms, where the rod's speed swings by up to 4% of v0; from 3 ms on the grains feel the
// rod's swings (the spring, k = 1e8 dyne/cm at 6 ms, no longer much stiffer than the
// grains' contacts under the tip), so the longer periods are simulated (mount).
DeckVars mount(double a)
{
  const double T = a * 1e-3, k = MOUNT_MASS * std::pow(2.0 * M_PI / T, 2);
  return {{"mount_k", deck_number(k)}, {"mount_c", deck_number(2.0 * MOUNT_ZETA * std::sqrt(k * MOUNT_MASS))},
          {"mount_m", deck_number(MOUNT_MASS)}};
}
std::vector<double> mount_filter(const std::vector<double> &F, double dt, double a)
{
  SensorChain c;
  c.mount.period = a * 1e-3;
  c.mount.zeta = MOUNT_ZETA;
  c.mount.reads_damper = true;
  return sensor_response(F, dt, c);
}
// force_scale: a = the measured force's relative scale error. A load cell's gain or
// calibration, or grains of another density than the header's (the inertial peak and the
// lithostatic term both go as rho_g): the same uniform scale of F, which no trace tells
// apart. Exactly linear in F, so it is a transform at any magnitude.
std::vector<double> scale_force(const std::vector<double> &F, double, double a)
{
  std::vector<double> out(F.size());
  for (std::size_t i = 0; i < F.size(); ++i) out[i] = (1.0 + a) * F[i];
  return out;
}
DeckVars ramp(double a) { return {{"ramp", deck_number(a)}}; }
// cohesion: the JKR surface energy of pair granular (inputs/model/contact.lmp), pour and push
DeckVars cohesion(double a) { return {{"cohesion", deck_number(a)}}; }
// cohesion_dmt: the DMT surface energy of a constant pull-off 4 pi gamma R_eff while grains
// touch (inputs/model/cohesion_dmt.lmp, through contact.lmp), pour and push
DeckVars cohesion_dmt(double a) { return {{"cohesion_dmt", deck_number(a)}}; }
// rod_friction: the rod-grain friction's offset from the grains' own (contact.lmp dmu_rod)
DeckVars rod_friction(double a) { return {{"dmu_rod", deck_number(a)}}; }
std::string packing_mu(double a)
{
  // the pour's friction sets phi_0 (docs/calibration.md: 0.594 -> 0.574 for mu 0.1 -> 0.5);
  // the magnitude is the pour friction's offset from the push's 0.3, reported with the
  // phi_0 shift it made
  return deck_number(0.3 + a);
}

// friction: the grains' sliding friction, pour and push alike (the calibration's one
// number: a data set whose grains are rougher or smoother than the calibrated 0.3)
std::string friction_mu(double a) { return deck_number(0.3 + a); }

}    // namespace

const std::vector<Effect> &effect_library()
{
  static const std::vector<Effect> lib = {
      {"rolling_resistance", "rolling friction between grains (pair granular, rolling sds): stand-in for non-spherical beads",
       "rolling friction coefficient mu_r", true, {0.1, 0.3}, true, rolling, none, "", nullptr},
      // Knots are what the cold cache costs (a pour-level knot: two pours and six pushes;
      // a push-only one: six pushes; docs/performance.md), so each effect has as few as its
      // signature's shape needs. One knot each: their signatures in bench are at the noise
      // (docs/gap-validation.md).
      {"polydispersity", "grain diameters uniform in d_g (1 +- w)", "relative half-width w", true, {0.25}, true,
       poly, none, "", nullptr},
      {"sidewalls", "a frictional container (walls at x, y = 0 and 8 cm) instead of periodic x, y",
       "wall friction coefficient", true, {0.6}, true, walls, none, "", nullptr},
      // measurement_chain: up to 2 ms a filter on the baseline's own traces (Effect::transform),
      // knots that cost nothing, placed where the signature bends (a factor of about 1.5 from
      // 0.2 ms: 5 kHz, the 1e-4 s traces' Nyquist frequency); beyond, where the rod's motion
      // feeds back into the grains, pushes with the mount on the baseline's beds at 4 and
      // 10 ms (the fit reaches 11.5 ms: real load cells with the rod's mass ring at 100 Hz to
      // several kHz). The reference value stays 0.7 ms, the first knot of the library before
      {"measurement_chain", "force sensor on a spring-damper mount (100 g, damping ratio 0.2; fix rod/drive mount): "
       "a filter on the baseline's force up to 2 ms", "mount natural period, ms", false,
       {0.2, 0.3, 0.45, 0.7, 1, 1.4, 2, 4, 10}, true, none, mount, "", nullptr, false, mount_filter, 2.0, 0.7},
      // ramp: linear from the baseline to its first knot (a ramp under 0.5 cm ends before contact)
      {"actuator_ramp", "actuator speed rising linearly from 0 to v0 over a travel (fix rod/drive ramp)",
       "ramp travel, cm (the rod starts 0.5 cm above the bed: shorter ramps end before contact)", false,
       {1.6, 3.2}, true, none, ramp, "", nullptr},
      {"packing", "bed prepared at another packing fraction (poured with another friction, pushed with 0.3)",
       "pour friction minus 0.3", true, {-0.2, 0.3}, false, none, none, "", packing_mu},
      // one knot: smoother grains by linear response through the baseline (gap_fit.cpp)
      {"friction", "grain sliding friction other than the calibrated 0.3, in the pour and the push (beds poured with it)",
       "friction coefficient minus 0.3", true, {0.15}, false, none, none, "", friction_mu, true},
      {"contact_stiffness", "contact stiffness kn = kt scaled (timestep scaled with the contact time)",
       "log10(k / 1e9 dyne/cm^2)", true, {-0.6, 0.6}, false, stiffness, none, "", nullptr},
      // strongly cohesive grains: JKR pull-off 3 pi gamma R_eff. What the rod feels is
      // pull-off against the contact forces it works against (a bench grain at 2-4 cm carries
      // about rho_g g z d_g^2 = 1000-1900 dyne), not against a grain's weight (98.6 dyne): up to
      // gamma = 300 (pull-off 280 dyne, Bond number 3) the bench force moves within two beds'
      // noise; 1000 and 3000 (pull-off 940 and 2800 dyne) move it by up to 26% and 68% at
      // 50 cm/s, and the beds still settle (docs/gap.md, "Cohesion at bench")
      {"cohesion", "strongly cohesive grains stick (pull-off near the contact forces): pair granular's JKR cohesive normal law in the pour and the push",
       "surface energy gamma, erg/cm^2 (pull-off 3 pi gamma R_eff)", true, {1000, 3000}, true, cohesion, none, "", nullptr},
      // cohesion of the other common law (DMT): a constant pull-off F_c = 4 pi gamma R_eff while
      // grains touch, no hysteresis (JKR's contact holds past zero overlap). Knots at the JKR
      // knots' pull-offs (940 and 2800 dyne) within 7%: 800 and 2400 give F_c = 1005 and 3016
      // dyne on bench grains (R_eff 0.1 cm), so the two laws are weighed at equal pull-off.
      // Opt-in (--effects default,cohesion_dmt): in the default library its knots moved the
      // pooled noise model enough to flip two marginal seed sets of cohesion right -> miss.
      {"cohesion_dmt", "cohesive grains of the DMT law: a constant pull-off while grains touch (pair table "
       "through hybrid/scaled on the bench law) in the pour and the push",
       "DMT surface energy gamma, erg/cm^2 (pull-off 4 pi gamma R_eff)", true, {800, 2400}, true, cohesion_dmt, none,
       "", nullptr, false, nullptr, INFINITY, NAN, false, true},
      // the rod's surface is not the grains' material: steel on glass about 0.1-0.2, a rough
      // or coated rod up to 0.6; in the push only, so paired on the baseline's beds
      {"rod_friction", "rod-grain sliding friction other than the grain-grain one (its own pair coefficients)",
       "rod-grain friction minus grain-grain friction", false, {-0.2, 0.3}, false, none, rod_friction, "", nullptr},
      // force_scale: the baseline's traces times (1 + a), nothing simulated; its confirming
      // runs are the baseline's on fresh beds, scaled. Every feature (bin means, fluctuation
      // levels, band amplitudes) is homogeneous of degree one in F, so the signature is
      // exactly linear in a and the interpolation through 0 and one knot a side is exact:
      // knots at +-0.25 make the fit reach +-0.31, a forgotten tare or a wrong density
      // (10 to 20%, up to 25%) inside it. Reference 0.1: the mistakes it is here for are
      // 10 to 20%; a calibrated load cell's 1 to 2% is below anything a bed's noise shows.
      {"force_scale", "measured force (1 + a) times the grains': a sensor's calibration or gain error, or grains of "
       "another density than the header's (the two scale F alike)", "relative scale error of the force", false,
       {-0.25, 0.25}, false, none, none, "", nullptr, false, scale_force, INFINITY, 0.1, true},
  };
  return lib;
}

bool common_in_labs(const Effect &e)
{
  // a lab calibrates its grains by one friction and one pour, its force by one load cell on
  // one mount, its rod by its material: these are the numbers most often off (docs/gap.md,
  // "Which"); the rest (cohesion, rolling shape, stiffness, walls, ramp) are set-up specific
  static const char *const common[] = {"force_scale", "friction", "packing", "measurement_chain", "rod_friction"};
  for (const char *n : common)
    if (e.name == n) return true;
  return false;
}

const Effect *find_effect(const std::string &name)
{
  for (const auto &e : effect_library())
    if (e.name == name) return &e;
  return nullptr;
}

std::string effect_sweep_name(const Effect &e, double a) { return e.name + "_" + deck_number(a); }

bool by_transform(const Effect &e, double a) { return e.transform && a <= e.transform_max; }

bool has_simulated_knots(const Effect &e)
{
  for (double a : e.knots)
    if (!by_transform(e, a)) return true;
  return false;
}

const Effect *transform_part(const Effect &e)
{
  if (!e.transform) return nullptr;
  if (!has_simulated_knots(e)) return &e;
  // one copy per library effect, made once (the library is fixed), so pointers stay valid
  static const std::vector<Effect> parts = [] {
    std::vector<Effect> out;
    for (const Effect &x : effect_library()) {
      if (!x.transform || !has_simulated_knots(x)) continue;
      Effect part = x;
      part.knots.clear();
      for (double a : x.knots)
        if (by_transform(x, a)) part.knots.push_back(a);
      out.push_back(part);
    }
    return out;
  }();
  for (const Effect &x : parts)
    if (x.name == e.name) return &x;
  return nullptr;
}

double reference_magnitude(const Effect &e)
{
  return std::isfinite(e.reference) ? e.reference : e.knots.empty() ? 0.0 : e.knots[0];
}

}    // namespace granpen
