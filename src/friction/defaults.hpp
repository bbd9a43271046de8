#pragma once
// The friction model's default parameters, the one place they are written
// (the laws' members and the configuration's defaults both read them):
// mu0 and s_c are the paper's (Fernandez et al. 2013, Eq. 1 and Fig. 1:
// mu0 = 0.1, s_c = 5e-5); s_lim, where we hold mu at mu(s_lim) beyond the
// lubrication regime, is ours (docs/model.md "Friction").
namespace dilatant::friction_defaults {

inline constexpr double kMu0 = 0.1;
inline constexpr double kSc = 5e-5;
inline constexpr double kSlim = 0.1;

}  // namespace dilatant::friction_defaults
