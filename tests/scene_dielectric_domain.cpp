// A glass IOR some table does not cover (1.1 <= ior < 1.3: ggx-fresnel-albedo starts at 1.3, the
// glass tables at 1.1) plans every table whose domain holds it, and a note names what is left;
// an IOR no dielectric table covers still plans the material's other tables.
#include <catch2/catch.hpp>

#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;

namespace {
using Names = std::vector<std::string>;

Plan GlassPlan(const std::string& ior, const std::string& extra = "") {
  return PlanText(OneMaterialGltf(
      R"({"name": "Glass", "pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.2},
      "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}, )" +
      extra + R"("KHR_materials_ior": {"ior": )" + ior + "}}}"));
}

bool HasPrefix(const Names& names, const std::string& prefix) {
  for (const std::string& n : names)
    if (n.rfind(prefix, 0) == 0) return true;
  return false;
}
}  // namespace

TEST_CASE("An IOR below fresnel-albedo's domain plans the glass tables and notes the rest",
          "[scene][plan]") {
  Plan plan = GlassPlan("1.14");
  Names names = TableNames(plan);
  INFO(::Catch::Detail::stringify(names));
  CHECK(!HasPrefix(names, "ggx-fresnel-albedo"));
  CHECK(HasPrefix(names, "ggx-dielectric-albedo-r-r0.2-ior1.14"));
  CHECK(HasPrefix(names, "ggx-dielectric-albedo-t-r0.2-ior1.14"));
  CHECK(HasPrefix(names, "ggx-dielectric-btdf-split-sum-r0.2-ior1.14"));
  CHECK(HasPrefix(names, "ggx-dfg-r0.2"));
  const PlanNote* note = FindNote(plan, SceneNote::Kind::NotYet, "ggx-fresnel-albedo");
  REQUIRE(note);
  CHECK(note->why.find("eta 1.14 is outside its domain [1.3, 3]") != std::string::npos);
  CHECK(note->why.find("not planned") != std::string::npos);
  CHECK(note->materials == Names{"'Glass' (/materials/0)"});
}

TEST_CASE("An IOR range across a domain's end is planned over the part inside, with a note",
          "[scene][plan]") {
  // ior 1.3 with dispersion 20: 1.15..1.45 (KHR_materials_dispersion).
  Plan plan = GlassPlan("1.3", R"("KHR_materials_dispersion": {"dispersion": 20}, )");
  Names names = TableNames(plan);
  INFO(::Catch::Detail::stringify(names));
  CHECK(HasPrefix(names, "ggx-fresnel-albedo-r0.2-ior1.3-1.45"));
  CHECK(HasPrefix(names, "ggx-dielectric-albedo-r-r0.2-ior1.15-1.45"));
  const PlanNote* note = FindNote(plan, SceneNote::Kind::NotYet, "ggx-fresnel-albedo");
  REQUIRE(note);
  CHECK(note->why.find("planned over the rest") != std::string::npos);
}

TEST_CASE("An IOR no dielectric table covers still plans the material's GGX lobe",
          "[scene][plan]") {
  Plan plan = GlassPlan("1.05");
  CHECK(TableNames(plan) == Names{"ggx-dfg-r0.2", "ggx-albedo-r0.2", "ggx-albedo-avg-r0.2"});
  CHECK(FindNote(plan, SceneNote::Kind::NotYet, "ggx-fresnel-albedo"));
  CHECK(FindNote(plan, SceneNote::Kind::NotYet, "ggx-dielectric-albedo-r"));
}
