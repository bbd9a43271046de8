# Precompiled headers: the heavy header-only libraries parsed once per target
# instead of once per source file (docs/testing.md "What changed" has the
# measurements). Every source still includes what it uses; the header is only
# forced in front, so a build with -DDILATANT_PCH=OFF compiles the same code
# (and shows a missing include).
option(DILATANT_PCH "Precompile the heavy library headers" ON)

# Headers that most of the library's sources reach: Eigen's fixed-size vectors
# (geometry/vec3.hpp, in nearly every file), toml++ (io/config.hpp), fmt, JSON,
# and the standard containers and streams.
set(DILATANT_PCH_COMMON
  <algorithm> <array> <cmath> <cstdint> <filesystem> <fstream> <functional> <map>
  <memory> <optional> <sstream> <string> <string_view> <vector>
  <Eigen/Core> <Eigen/Geometry> <fmt/format.h> <nlohmann/json.hpp> <toml++/toml.h>)

# dilatant_precompile_headers(TARGET [EXTRA_HEADER ...]): the common set plus
# the target's own heavy headers (GoogleTest for the tests, CLI11 for the CLI).
function(dilatant_precompile_headers target)
  if(DILATANT_PCH)
    target_precompile_headers(${target} PRIVATE ${DILATANT_PCH_COMMON} ${ARGN})
  endif()
endfunction()
