#include "friction/tangential_problem.hpp"

namespace dilatant {

const char* regime_name(Regime r) {
  switch (r) {
    case Regime::Open:
      return "open";
    case Regime::Stick:
      return "stick";
    case Regime::BoundaryLubricated:
      return "bl";
    case Regime::Hydrodynamic:
      return "hd";
    case Regime::Frictionless:
      return "frictionless";
  }
  return "unknown";
}

}  // namespace dilatant
