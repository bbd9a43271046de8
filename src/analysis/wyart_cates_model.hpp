#pragma once
// The Wyart–Cates model of shear thickening (Wyart & Cates, PRL 112, 098302,
// 2014, Eqs. 1-3; parametrised as in Singh, Mari, Denn & Morris, J. Rheol. 62,
// 457, 2018, Eqs. 4-6) and the flow states it implies.
//
// A fraction f of the contacts is frictional; it grows with the stress, and
// the jamming fraction moves from the frictionless phi_0 to the frictional
// phi_m < phi_0:
//
//     f(sigma)        = exp(-(sigma*/sigma)^beta)                    (SMDM Eq. 5)
//     phi_J(sigma)    = f phi_m + (1 - f) phi_0                      (WC Eq. 2)
//     eta(sigma, phi) = A eta_f (1 - phi/phi_J(sigma))^(-alpha)      (WC Eq. 3)
//
// beta = 1 and alpha = 2 in both papers. A absorbs the solvent viscosity: the
// prefactor A here is a viscosity (A eta_f), in the units of the data.
//
// Flow states under an imposed stress (WC Fig. 2; SMDM Fig. 8). The
// stress-controlled flow curve gamma_dot(sigma) = sigma/eta(sigma) turns back
// (an S-shape: DST) where
//
//     d ln gamma_dot / d ln sigma = 1 - d ln eta / d ln sigma < 0,
//
// and with x = (sigma*/sigma)^beta, Delta = phi_0 - phi_m, d f/d ln sigma = beta x f:
//
//     d ln eta / d ln sigma = alpha beta phi Delta x e^(-x) / (phi_J (phi_J - phi)).   (*)
//
// (*) depends on sigma only through x, so the lowest phi with an S-shape,
// phi_DST, does not depend on sigma* or A, and the stresses of the S scale
// with sigma*. At phi = phi_m, (*) tends to alpha beta as sigma -> infinity, so
// with alpha beta > 1 (2 for the papers' exponents) phi_DST < phi_m. For
// phi_m <= phi < phi_0 the suspension jams above the shear-jamming stress,
// where phi_J(sigma) = phi:
//
//     sigma_SJ(phi) = sigma* [ln(Delta / (phi_0 - phi))]^(-1/beta),
//
// the shear-jamming line (WC Fig. 2); at phi >= phi_0 it never flows.
#include <string>

namespace dilatant::analysis {

struct WyartCatesParameters {
  double phi_0 = 0.0;       // frictionless jamming fraction
  double phi_m = 0.0;       // frictional jamming fraction
  double sigma_star = 0.0;  // onset stress of frictional contacts
  double A = 0.0;           // viscosity prefactor, A eta_f
  double alpha = 2.0;
  double beta = 1.0;
};

double frictional_fraction(const WyartCatesParameters& p, double sigma);
double jamming_fraction(const WyartCatesParameters& p, double sigma);
// +infinity where phi >= phi_J(sigma).
double wyart_cates_viscosity(const WyartCatesParameters& p, double phi, double sigma);
// d ln eta / d ln sigma, Eq. (*); +infinity where phi >= phi_J(sigma).
double thickening_slope(const WyartCatesParameters& p, double phi, double sigma);

// sigma_SJ(phi): +infinity below phi_m (never jams), 0 at or above phi_0 (never
// flows); +infinity too when phi_m >= phi_0 (no thickening).
double shear_jamming_stress(const WyartCatesParameters& p, double phi);

// The stresses between which the stress-controlled curve at phi turns back
// (d ln gamma_dot/d ln sigma < 0); both NaN when it never does. For
// phi_m <= phi < phi_0, `high` is sigma_SJ: the branch ends in jamming.
struct TurningRange {
  double low = 0.0;
  double high = 0.0;
  bool exists() const { return low == low; }  // not NaN
};
TurningRange turning_range(const WyartCatesParameters& p, double phi);

// The lowest phi whose flow curve turns back, and the stress at which its
// slope first reaches 0 there. NaN when the model does not thicken
// (phi_m >= phi_0). When alpha beta <= 1 and no curve below phi_m turns back,
// phi_DST = phi_m: DST appears only as shear jamming.
struct DstOnset {
  double phi = 0.0;
  double stress = 0.0;
};
DstOnset dst_onset(const WyartCatesParameters& p);

// Where (phi, sigma) lies: below phi_DST and off the S every curve flows
// ("flows"); on the S-shaped part ("turns_back": stress-controlled flow is
// unstable, DST); beyond phi_J ("jammed").
enum class FlowState { Flows, TurnsBack, Jammed };
FlowState flow_state(const WyartCatesParameters& p, double phi, double sigma);
std::string flow_state_name(FlowState s);

// The regime of the whole flow curve at phi: "cst" below phi_DST, "dst" up
// to phi_m, "shear_jamming" up to phi_0, "no_flow" above.
std::string flow_curve_regime(const WyartCatesParameters& p, double phi);

}  // namespace dilatant::analysis
