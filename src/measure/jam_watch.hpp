#pragma once
// Whether a stress-driven cell has jammed: its drive advanced less than
// kJamStrain within a window of kJamWindow time units (code units
// R sqrt(rho_p/tau); a Newtonian flow at lambda = 0.01 still shears ~1e-2 in
// that time). Part of the checkpoint, so a resumed run keeps its window.
namespace dilatant {

struct JamWatch {
  static constexpr double kJamWindow = 50.0;
  static constexpr double kJamStrain = 1e-4;

  double window_strain = 0.0;  // strain and time at the start of the current window
  double window_time = 0.0;
  bool jammed = false;

  // After each step: at the window's end, decide and open the next window.
  void observe(double time, double strain) {
    if (time - window_time < kJamWindow) return;
    jammed = strain - window_strain < kJamStrain;
    window_time = time;
    window_strain = strain;
  }
};

}  // namespace dilatant
