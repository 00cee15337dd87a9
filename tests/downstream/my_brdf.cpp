// An engine's own lobe for kiln_bake(MODEL_SOURCE ...): a Lambert lobe with a retro-reflective
// term, f = (1 + r (o.l)^+) / pi (kiln/model_abi.h).
#include <kiln/model_abi.h>

extern "C" int kiln_model_abi_version() { return KILN_MODEL_ABI_VERSION; }
extern "C" const char* kiln_model_id() { return "my-brdf"; }
extern "C" int kiln_model_is_specular() { return 0; }
extern "C" double kiln_model_eval(const double wo[3], const double wi[3], double r) {
  double ol = wo[0] * wi[0] + wo[1] * wi[1] + wo[2] * wi[2];
  return (1 + r * (ol > 0 ? ol : 0)) / 3.14159265358979323846;
}
