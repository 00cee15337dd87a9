// Measured complex indices of refraction at one wavelength (seed 004's table; the seed writes
// n - ik, kiln stores k >= 0, which gives the same reflectance).
#pragma once
#include <string>
#include <vector>

#include "baker/models/fresnel.h"

namespace kiln {

struct MeasuredMaterial {
  const char* name;
  double n, k;    ///< eta = n + i k
  double seedF0;  ///< F0 as the seed prints it (3 digits), or -1 where it gives none
  double F0() const { return F0FromEta(n, k); }
  bool Conductor() const { return k > 0; }
};

/// Seed 004's table, in its order.
inline const std::vector<MeasuredMaterial>& MeasuredMaterials() {
  static const std::vector<MeasuredMaterial> table = {
      {"iron", 2.36, 0, 0.164},     {"iron-oxide", 3.01, 0, -1}, {"gold", 0.34, 3.2, 0.887},
      {"silver", 0.17, 3.4, -1},    {"copper", 0.6, 3.6, -1},    {"quartz", 1.45, 0, 0.034},
      {"sapphire", 1.76, 0, 0.076}, {"water", 1.33, 0, -1},      {"titanium-oxide", 2.52, 0, -1},
      {"ivory", 1.54, 0, -1},       {"carbon", 2.0, 1.0, 0.2},
  };
  return table;
}

/// The material with this name, or nullptr.
inline const MeasuredMaterial* FindMaterial(const std::string& name) {
  for (const MeasuredMaterial& m : MeasuredMaterials())
    if (name == m.name) return &m;
  return nullptr;
}

}  // namespace kiln
