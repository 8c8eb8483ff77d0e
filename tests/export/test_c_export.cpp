// The exported C header (export/c_export.hpp) against the library: each header is compiled with the
// system C compiler in strict C99 (cc -std=c99 -Wall -Wextra -Werror -pedantic) into a small
// program that prints the law over a velocity grid and a fixed-step run over a rig-like record;
// the numbers must be the library's.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "error_message.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/export/c_export.hpp"
#include "temp_dir.hpp"

namespace frictionlab {
namespace {

using testing::TempDir;

// Double: the header runs the library's formulas in the library's order on the same libm, so the
// values agree to rounding; 1e-12 leaves room for a compiler contracting a multiply-add that the
// library's build does not, and nothing more.
constexpr double kRelTol = 1e-12;
// Float: float's unit roundoff u is 6e-8 and a law's value passes through ~20 roundings, but the
// bristle laws lose more: sigma0 z + sigma1 dz/dt cancels to the force from terms sigma1 |v|
// larger, so at high speed the error is about (sigma1 / sigma2) u of the force, 4.7e-5 for the
// 1995 set (sigma1 = 316, sigma2 = 0.4; 2.6e-5 seen). 2e-4 of the run's force scale bounds that
// with margin while still catching a wrong formula (off by 1e-3 or more).
constexpr double kFloatTol = 2e-4;

std::string literal(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string c_array(const char* type, const std::string& name, const std::vector<double>& values) {
  // Not static: an array a program leaves unused must not fail -Werror (unused-const-variable).
  std::string s = "const " + std::string(type) + " " + name + "[" + std::to_string(values.size()) + "] = {";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + literal(values[i]);
  return s + "};\n";
}

// Writes header.h and main.c, compiles them strictly and returns the numbers the program prints.
std::vector<double> compile_and_run(const TempDir& dir, const std::string& header, const std::string& main_c) {
  dir.file("law.h", header);
  dir.file("main.c", "#include <stdio.h>\n#include \"law.h\"\n" + main_c);
  const std::string exe = dir.file("prog"), log = dir.file("cc.log");
  const std::string cc = "cc -std=c99 -Wall -Wextra -Werror -pedantic -O2 -o '" + exe + "' '" + dir.file("main.c") +
                         "' -lm > '" + log + "' 2>&1";
  if (std::system(cc.c_str()) != 0) {
    std::ifstream in(log);
    std::stringstream s;
    s << in.rdbuf();
    ADD_FAILURE() << "the header does not compile strictly:\n" << s.str() << "\n--- header ---\n" << header;
    return {};
  }
  const std::string out = dir.file("out.txt");
  EXPECT_EQ(std::system(("'" + exe + "' > '" + out + "'").c_str()), 0);
  std::ifstream in(out);
  std::vector<double> values;
  for (std::string word; in >> word;) values.push_back(std::strtod(word.c_str(), nullptr));
  return values;
}

// Rounds to the C program's precision (its inputs are literals of that type).
double as_real(double x, bool single) { return single ? static_cast<double>(static_cast<float>(x)) : x; }

void expect_close(const std::vector<double>& c, const std::vector<double>& lib, bool single, const std::string& what) {
  ASSERT_EQ(c.size(), lib.size()) << what;
  double scale = 0;
  for (double x : lib) scale = std::max(scale, std::abs(x));
  for (std::size_t i = 0; i < lib.size(); ++i) {
    ASSERT_TRUE(std::isfinite(c[i])) << what << " [" << i << "]";
    const double tol = single ? kFloatTol * scale : kRelTol * std::abs(lib[i]);
    ASSERT_LE(std::abs(c[i] - lib[i]), tol) << what << " [" << i << "]: C " << c[i] << ", library " << lib[i];
  }
}

// A velocity grid through every feature: rest, both signs, the Stribeck and band scales, the
// table's points and beyond, and 400 log-spaced speeds from 1e-7 to 10 m/s.
std::vector<double> velocity_grid() {
  std::vector<double> v = {0.0, 1e-3, -1e-3, 2e-3, -2e-3, 5e-4, -5e-4, 1e-4, -1e-4, 0.05, -0.05, 0.3, -0.3, 12.0, -12.0};
  for (int i = 0; i < 400; ++i) {
    const double s = std::pow(10.0, -7.0 + 8.0 * i / 399.0);
    v.push_back(s);
    v.push_back(-s * 1.013);
  }
  return v;
}

// A rig-like record at a 1 kHz drive: a velocity reversing sinusoidally (with a constant-speed
// stretch), Gaussian noise, an offset, quantised to an encoder's velocity resolution, on a
// jittered clock; seeded.
struct Record {
  std::vector<double> t, dt, x, v, r, drive;
};

Record rig_record(unsigned seed, int n = 3000) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 2e-4);
  std::uniform_real_distribution<double> jitter(-5e-5, 5e-5);
  constexpr double kQuantum = 1e-5;  // m/s: velocity from 1 um encoder counts at 10 kHz
  Record rec;
  double t = 0, x = 0;
  for (int k = 0; k < n; ++k) {
    const double dt = 1e-3 + jitter(rng);
    t += dt;
    const double ideal = k < n / 2 ? 0.02 * std::sin(2 * M_PI * 1.5 * t) : 0.004 + 0.001 * std::sin(6 * t);
    const double v = std::round((ideal + 1e-4 + noise(rng)) / kQuantum) * kQuantum;
    x += v * dt;
    rec.t.push_back(t);
    rec.dt.push_back(dt);
    rec.v.push_back(v);
    rec.x.push_back(x);
    rec.r.push_back(x + 2e-5 * std::sin(3 * t));
    rec.drive.push_back(1.2 * std::tanh(v / 1e-3) + 0.5 * v + 0.05 * noise(rng) / 2e-4);
  }
  return rec;
}

struct LawCase {
  std::string name;
  FrictionLaw law;
};

std::vector<LawCase> static_laws() {
  Stribeck s1{1.0, 1.5, 0.001, 1.0, 0.4}, s13{2.0, 3.1, 0.004, 1.3, 0.7};
  Smooth sm_tanh{}, sm_atan{};
  sm_tanh.Fs = 1.4;
  sm_tanh.Fv = 0.2;
  sm_atan.shape = SmoothShape::atan;
  Asymmetric<Stribeck> as;
  as.pos = {1.1, 1.6, 0.002, 2.0, 0.35};
  as.neg = {0.8, 1.3, 0.001, 1.5, 0.45};
  Asymmetric<Coulomb> ac;
  ac.pos.Fc = 0.7;
  ac.neg.Fc = 0.9;
  Asymmetric<Viscous> av;
  av.pos.Fv = 0.3;
  av.neg.Fv = 0.5;
  Asymmetric<CoulombViscous> acv;
  acv.pos = {1.0, 0.2};
  acv.neg = {1.3, 0.25};
  Asymmetric<StaticCoulombViscous> ascv;
  ascv.pos = {1.5, 1.0, 0.1};
  ascv.neg = {1.9, 1.2, 0.15};
  return {
      {"coulomb", Coulomb{0.8}},
      {"viscous", Viscous{0.35}},
      {"coulomb_viscous", CoulombViscous{1.1, 0.3}},
      {"static_coulomb_viscous", StaticCoulombViscous{1.5, 1.0, 0.1}},
      {"stribeck", Stribeck{}},
      {"stribeck_delta1", s1},
      {"stribeck_delta13", s13},
      {"karnopp", Karnopp{1.5, 1.0, 0.1, 2e-4}},
      {"table", Table({-0.2, -0.05, -0.004, -0.001, 0.001, 0.004, 0.03, 0.2}, {-2.1, -1.3, -1.05, -1.6, 1.4, 1.0, 1.2, 1.9})},
      {"table_mirrored", Table({0.001, 0.01, 0.1}, {1.2, 0.9, 1.4})},
      {"smooth_tanh", sm_tanh},
      {"smooth_atan", sm_atan},
      {"coulomb_asymmetric", ac},
      {"viscous_asymmetric", av},
      {"coulomb_viscous_asymmetric", acv},
      {"static_coulomb_viscous_asymmetric", ascv},
      {"stribeck_asymmetric", as},
  };
}

std::vector<LawCase> dynamic_laws() {
  LuGre lugre_vd{};
  lugre_vd.vd = 0.002;
  lugre_vd.delta = 1.5;
  Dahl dahl_half{2e4, 0.9, 0.5}, dahl_two{2e4, 0.9, 2.0};
  Gms gms{};
  return {
      {"lugre", LuGre{}},           {"lugre_vd", lugre_vd},     {"dahl", Dahl{}},         {"dahl_alpha_half", dahl_half},
      {"dahl_alpha_two", dahl_two}, {"elastoplastic", ElastoPlastic{}}, {"gms", gms},
  };
}

// The law and precision a parameterised test runs (index into `laws`, float or double).
struct ExportCase {
  LawCase law;
  bool single;
  CExportOptions options;
};
ExportCase law_case(const std::vector<LawCase>& laws, std::tuple<int, bool> param, const std::string& prefix = "friction") {
  ExportCase c{laws.at(static_cast<std::size_t>(std::get<0>(param))), std::get<1>(param), {}};
  c.options.single_precision = c.single;
  c.options.prefix = prefix;
  return c;
}

// --- static laws: F(v) over the grid and the force with stiction ---

class StaticLawExport : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(StaticLawExport, MatchesLibraryOverVelocityGridAndAtRest) {
  const auto [c, single, o] = law_case(static_laws(), GetParam());
  SCOPED_TRACE(c.name + (single ? " (float)" : " (double)"));
  TempDir dir;
  const std::string header = c_header(c.law, o);
  const char* type = single ? "float" : "double";
  std::vector<double> v = velocity_grid();
  // (v, applied) pairs: at rest below, at and above each breakaway level, and inside Karnopp's band.
  std::vector<double> sv, sa;
  for (double vv : {0.0, 1e-4, -1e-4, 0.5}) {
    for (double a : {0.0, 0.4, -0.4, 1.45, -1.45, 1.5, -1.5, 2.5, -2.5, 1.89, -1.91}) {
      sv.push_back(vv);
      sa.push_back(a);
    }
  }
  const std::string main_c = c_array(type, "vg", v) + c_array(type, "sv", sv) + c_array(type, "sa", sa) +
                             "int main(void) {\n  unsigned i;\n"
                             "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)friction_friction(vg[i]));\n"
                             "  for (i = 0; i < sizeof sv / sizeof sv[0]; ++i) printf(\"%.17g\\n\", (double)friction_friction_stuck(sv[i], sa[i]));\n"
                             "  return 0;\n}\n";
  const std::vector<double> out = compile_and_run(dir, header, main_c);
  std::vector<double> lib;
  for (double x : v) lib.push_back(c.law.sliding(as_real(x, single)));
  for (std::size_t i = 0; i < sv.size(); ++i) lib.push_back(c.law.force(as_real(sv[i], single), as_real(sa[i], single)));
  expect_close(out, lib, single, c.name);
}

INSTANTIATE_TEST_SUITE_P(AllStaticLaws, StaticLawExport,
                         ::testing::Combine(::testing::Range(0, static_cast<int>(static_laws().size())), ::testing::Bool()));

// --- dynamic laws: the steady map over the grid and a fixed-step run ---

class DynamicLawExport : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(DynamicLawExport, MatchesLibraryFixedStepRunAndSteadyMap) {
  const auto [c, single, o] = law_case(dynamic_laws(), GetParam(), "axis1");
  SCOPED_TRACE(c.name + (single ? " (float)" : " (double)"));
  TempDir dir;
  const std::string header = c_header(c.law, o);
  const char* type = single ? "float" : "double";
  const Record rec = rig_record(17u + static_cast<unsigned>(std::get<0>(GetParam())));
  // The record at 1 kHz, then steps far beyond any time constant (stable at any step), with a
  // standstill and a zero step.
  std::vector<double> v = rec.v, dt = rec.dt;
  for (double big : {0.5, 10.0, 1e3}) {
    for (double vv : {0.3, -0.3, 0.0, 2e-3, -5.0}) {
      v.push_back(vv);
      dt.push_back(big);
    }
  }
  v.push_back(0.01);
  dt.push_back(0.0);
  const std::vector<double> grid = velocity_grid();
  const std::string main_c =
      c_array(type, "vg", grid) + c_array(type, "v", v) + c_array(type, "dt", dt) +
      "int main(void) {\n  unsigned i;\n  axis1_state s;\n"
      "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)axis1_friction(vg[i]));\n"
      "  axis1_init(&s);\n"
      "  for (i = 0; i < sizeof v / sizeof v[0]; ++i) printf(\"%.17g\\n\", (double)axis1_update(&s, v[i], dt[i]));\n"
      "  return 0;\n}\n";
  const std::vector<double> out = compile_and_run(dir, header, main_c);
  std::vector<double> lib;
  for (double x : grid) lib.push_back(c.law.sliding(as_real(x, single)));
  ASSERT_GE(out.size(), lib.size());
  expect_close(std::vector<double>(out.begin(), out.begin() + static_cast<long>(lib.size())), lib, single,
               c.name + " steady map");
  std::vector<double> z(static_cast<std::size_t>(c.law.num_states()), 0.0), run;
  for (std::size_t k = 0; k < v.size(); ++k) run.push_back(c.law.step(z, as_real(v[k], single), as_real(dt[k], single)));
  expect_close(std::vector<double>(out.begin() + static_cast<long>(lib.size()), out.end()), run, single, c.name + " run");
}

INSTANTIATE_TEST_SUITE_P(AllDynamicLaws, DynamicLawExport,
                         ::testing::Combine(::testing::Range(0, static_cast<int>(dynamic_laws().size())), ::testing::Bool()));

// --- compensations ---

// friction_<function>(v) over the grid, from the header of `law` with `compensation`.
std::vector<double> band_output(const FrictionLaw& law, const CompensationParams& compensation, const std::string& function,
                                const std::vector<double>& grid, bool single) {
  TempDir dir;
  CExportOptions o;
  o.single_precision = single;
  o.compensation = compensation;
  return compile_and_run(dir, c_header(law, o),
                         c_array(single ? "float" : "double", "vg", grid) +
                             "int main(void) {\n  unsigned i;\n"
                             "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)friction_" +
                             function + "(vg[i]));\n  return 0;\n}\n");
}

class CompensationExport : public ::testing::TestWithParam<bool> {};

TEST_P(CompensationExport, FeedforwardAndFeedbackMatchLibraryAcrossTheirBands) {
  const bool single = GetParam();
  Asymmetric<Stribeck> as;
  as.pos = {1.1, 1.6, 0.002, 2.0, 0.35};
  as.neg = {0.8, 1.3, 0.001, 1.5, 0.45};
  for (const FrictionLaw& law : {FrictionLaw(as), FrictionLaw(LuGre{})}) {
    SCOPED_TRACE(law.name());
    std::vector<double> grid = velocity_grid();
    for (double b : {2e-3, -2e-3, 1.999e-3, -1.999e-3, 2.001e-3, -2.001e-3}) grid.push_back(b);
    const FeedforwardParams ff{2e-3};
    const FeedbackParams fb{5e-4};
    // The library's reference with the bands as the float header holds them, so that a velocity
    // on an edge falls on the same side in both.
    const FeedforwardParams ff_ref{as_real(ff.band, single)};
    const FeedbackParams fb_ref{as_real(fb.dead_band, single)};
    const FeedforwardCompensation feedforward(law, ff_ref);
    const FeedbackCompensation feedback(law, fb_ref);
    std::vector<double> lib_ff, lib_fb;
    for (double x : grid) {
      lib_ff.push_back(feedforward.force(as_real(x, single)));
      lib_fb.push_back(feedback.force(as_real(x, single)));
    }
    expect_close(band_output(law, ff, "feedforward", grid, single), lib_ff, single, "feedforward");
    const std::vector<double> out = band_output(law, fb, "feedback", grid, single);
    expect_close(out, lib_fb, single, "feedback");
    EXPECT_EQ(out.at(0), 0.0);  // v = 0 is inside the dead band
  }
}

TEST_P(CompensationExport, ObserversMatchLibraryFixedStepRun) {
  const bool single = GetParam();
  const char* type = single ? "float" : "double";
  const Record rec = rig_record(99u);
  std::vector<double> x = rec.x, v = rec.v, r = rec.r, drive = rec.drive, dt = rec.dt;
  // A long standstill (the observer integrates the position error) and a step of 10 s.
  for (int k = 0; k < 200; ++k) {
    x.push_back(x.back());
    v.push_back(0.0);
    r.push_back(x.back() + 1e-5);
    drive.push_back(0.3);
    dt.push_back(k == 199 ? 10.0 : 1e-3);
  }
  const std::string arrays = c_array(type, "x", x) + c_array(type, "v", v) + c_array(type, "r", r) +
                             c_array(type, "drive", drive) + c_array(type, "dt", dt);
  auto input = [&](std::size_t k) {
    CompensatorInput in;
    in.position = as_real(x[k], single);
    in.velocity = as_real(v[k], single);
    in.reference = as_real(r[k], single);
    in.drive = as_real(drive[k], single);
    return in;
  };
  {
    SCOPED_TRACE("lugre-observer");
    TempDir dir;
    CExportOptions o;
    o.single_precision = single;
    const LuGreObserverParams p{0.05};
    o.compensation = p;
    const std::vector<double> out = compile_and_run(
        dir, c_header(LuGre{}, o),
        arrays + "int main(void) {\n  unsigned i;\n  friction_lugre_observer_state s;\n"
                 "  friction_lugre_observer_init(&s, v[0]);\n"
                 "  for (i = 0; i < sizeof v / sizeof v[0]; ++i)\n"
                 "    printf(\"%.17g\\n\", (double)friction_lugre_observer_update(&s, x[i], v[i], r[i], dt[i]));\n"
                 "  return 0;\n}\n");
    const LuGreObserver obs(LuGre{}, p);
    double z = 0;
    obs.initial_states(input(0), {&z, 1});
    std::vector<double> lib;
    for (std::size_t k = 0; k < v.size(); ++k) lib.push_back(obs.update(input(k), {&z, 1}, as_real(dt[k], single)));
    expect_close(out, lib, single, "lugre-observer");
  }
  {
    SCOPED_TRACE("disturbance-observer");
    TempDir dir;
    CExportOptions o;
    o.single_precision = single;
    const DisturbanceObserverParams p{150.0, 2.3};
    o.compensation = p;
    const std::vector<double> out = compile_and_run(
        dir, c_header(Stribeck{}, o),
        arrays + "int main(void) {\n  unsigned i;\n  friction_disturbance_observer_state s;\n"
                 "  friction_disturbance_observer_init(&s, v[0]);\n"
                 "  for (i = 0; i < sizeof v / sizeof v[0]; ++i)\n"
                 "    printf(\"%.17g\\n\", (double)friction_disturbance_observer_update(&s, v[i], drive[i], dt[i]));\n"
                 "  return 0;\n}\n");
    const DisturbanceObserver obs(p);
    double z = 0;
    obs.initial_states(input(0), {&z, 1});
    std::vector<double> lib;
    for (std::size_t k = 0; k < v.size(); ++k) lib.push_back(obs.update(input(k), {&z, 1}, as_real(dt[k], single)));
    expect_close(out, lib, single, "disturbance-observer");
  }
}

INSTANTIATE_TEST_SUITE_P(DoubleAndFloat, CompensationExport, ::testing::Bool());

// --- the header's form ---

TEST(CExportForm, ParametersAtFullPrecisionOnlyMathHeaderNoAllocation) {
  CExportOptions o;
  o.prefix = "x_axis";
  o.compensation = FeedforwardParams{1e-3};
  const std::string h = c_header(LuGre{}, o);
  EXPECT_NE(h.find("static const double x_axis_sigma1 = 316.22776601683796;"), std::string::npos) << h;
  EXPECT_NE(h.find("static const double x_axis_ff_band = 0.001;"), std::string::npos);
  EXPECT_NE(h.find("#ifndef X_AXIS_FRICTION_H"), std::string::npos);
  std::size_t includes = 0;
  for (std::size_t at = h.find("#include"); at != std::string::npos; at = h.find("#include", at + 1)) ++includes;
  EXPECT_EQ(includes, 1u);
  EXPECT_NE(h.find("#include <math.h>"), std::string::npos);
  for (const char* banned : {"malloc", "calloc", "free(", "printf", "static double", "static float"})
    EXPECT_EQ(h.find(banned), std::string::npos) << banned;
  o.single_precision = true;
  const std::string f = c_header(LuGre{}, o);
  EXPECT_NE(f.find("static const float x_axis_sigma1 = 316.22776601683796f;"), std::string::npos) << f;
  EXPECT_NE(f.find("static const float x_axis_sigma0 = 100000.0f;"), std::string::npos);
  EXPECT_EQ(f.find("double"), std::string::npos);  // no double arithmetic on a float-only FPU
  EXPECT_NE(f.find("expf("), std::string::npos);
}

TEST(CExportErrors, CompensationThatDoesNotFitAndBadParametersNameTheKey) {
  using testing::error_of;
  CExportOptions o;
  o.compensation = LuGreObserverParams{};
  EXPECT_EQ(error_of([&] { c_header(Stribeck{}, o); }).rfind("lugre-observer: law = stribeck must be lugre", 0), 0u);
  o.compensation = DisturbanceObserverParams{100.0, 0.0};
  EXPECT_EQ(error_of([&] { c_header(Stribeck{}, o); }).rfind("disturbance-observer: inertia = 0 must be > 0", 0), 0u);
  o.compensation = FeedforwardParams{-1.0};
  EXPECT_EQ(error_of([&] { c_header(Stribeck{}, o); }), "feedforward: band = -1 must be > 0 (m/s or rad/s)");
  o.compensation = std::monostate{};
  for (const char* bad : {"", "1axis", "axis-1", "a b", "_x"}) {
    o.prefix = bad;
    EXPECT_EQ(error_of([&] { c_header(Coulomb{}, o); }).rfind("prefix '" + std::string(bad) + "' is not a C identifier", 0), 0u)
        << bad;
  }
  EXPECT_EQ(error_of([] { make_compensation("observer"); }),
            "compensation 'observer' is not known; valid types: feedforward, feedback, lugre-observer, disturbance-observer");
  EXPECT_EQ(error_of([] { make_compensation("feedforward", {{"gain", 1.0}}); }),
            "compensation feedforward has no parameter 'gain'; it has band");
  EXPECT_EQ(compensation_type(make_compensation("lugre-observer")), "lugre-observer");
  const auto dob = std::get<DisturbanceObserverParams>(make_compensation("disturbance-observer", {{"inertia", 2.5}}));
  EXPECT_EQ(dob.inertia, 2.5);
  EXPECT_EQ(dob.bandwidth, DisturbanceObserverParams{}.bandwidth);
  // The model's M is the default; an inertia given beats it.
  EXPECT_EQ(std::get<DisturbanceObserverParams>(make_compensation("disturbance-observer", {}, 3.0)).inertia, 3.0);
  EXPECT_EQ(std::get<DisturbanceObserverParams>(make_compensation("disturbance-observer", {{"inertia", 2.5}}, 3.0)).inertia,
            2.5);
}

}  // namespace
}  // namespace frictionlab

namespace frictionlab {
namespace {

// Load terms (one coefficient or two) and a temperature term over [10, 60] degC, for the exports
// at conditions.
LawEffects load_and_temperature(bool two_load_coefficients) {
  LawEffects e;
  e.load = LoadDependence{two_load_coefficients ? 0.08 : 0.05, 0.05};
  TemperatureDependence t;
  t.T_ref = 30.0;
  t.Fc_per_K = -0.004;
  t.Fv_per_K = -0.006;
  t.T_min = 10.0;
  t.T_max = 60.0;
  e.temperature = t;
  return e;
}

// A law with a position ripple (two harmonics, the second with a zero cosine amplitude): the
// header's PREFIX_ripple(q) and PREFIX_friction_at(v, q) (prefix "friction": friction_ripple,
// friction_friction_at) against the library's ripple(q) and sliding(v) + ripple(q) over positions
// across several periods, both precisions; a dynamic law's load term is refused naming its key.
class RippleExport : public ::testing::TestWithParam<bool> {};

FrictionLaw rippled_stribeck() {
  LawEffects e;
  e.ripple = PositionRipple{0.02, {0.6, 0.15}, {-0.4, 0.0}, {}, {}};
  return FrictionLaw(Stribeck{1.0, 1.5, 0.001, 1.0, 0.4}).with_effects(e);
}

TEST_P(RippleExport, RippleAndFrictionAtMatchLibrary) {
  const bool single = GetParam();
  const FrictionLaw law = rippled_stribeck();
  std::vector<double> q, v;
  for (int i = 0; i < 41; ++i) q.push_back(-0.05 + 0.0025 * i + 1e-4 * i * i / 7.0);  // m, across five periods
  for (int i = 0; i < 41; ++i) v.push_back(-0.2 + 0.01 * i + 1e-5);                    // m/s, both directions
  TempDir dir;
  CExportOptions o;
  o.single_precision = single;
  const std::string type = single ? "float" : "double";
  const std::vector<double> out = compile_and_run(
      dir, c_header(law, o),
      c_array(type.c_str(), "qg", q) + c_array(type.c_str(), "vg", v) +
          "int main(void) {\n  unsigned i;\n"
          "  for (i = 0; i < sizeof qg / sizeof qg[0]; ++i) printf(\"%.17g\\n\", (double)friction_ripple(qg[i]));\n"
          "  for (i = 0; i < sizeof qg / sizeof qg[0]; ++i) printf(\"%.17g\\n\", (double)friction_friction_at(vg[i], qg[i]));\n"
          "  return 0;\n}\n");
  std::vector<double> lib;
  for (double x : q) lib.push_back(law.ripple(as_real(x, single)));
  for (std::size_t i = 0; i < q.size(); ++i) lib.push_back(law.sliding(as_real(v[i], single)) + law.ripple(as_real(q[i], single)));
  expect_close(out, lib, single, "rippled stribeck");
}

// The feedforward and feedback of a law with a ripple: PREFIX_feedforward_at(vr, q[, load][, T])
// adds the ripple at the reference position q, PREFIX_feedback_at(v, q[, load][, T]) at the
// measured one, inside the band as outside it, against the library compensators' output() at the
// same inputs (reference = q for the feedforward, position = q for the feedback); a ripple alone
// and a ripple with load and temperature terms; both precisions, to expect_close's tolerances.
TEST_P(RippleExport, CompensationsAddTheRippleAtTheirPositionAsTheLibrary) {
  const bool single = GetParam();
  const std::string type = single ? "float" : "double";
  LawEffects with_conditions = load_and_temperature(true);
  with_conditions.ripple = PositionRipple{0.02, {0.6, 0.15}, {-0.4, 0.0}, {}, {}};
  const FrictionLaw both = FrictionLaw(Stribeck{1.0, 1.5, 0.001, 1.0, 0.4}).with_effects(with_conditions);
  // Velocities through both bands (2e-3 and 5e-4 m/s) and beyond; positions across five periods;
  // loads of both signs; temperatures inside [T_min, T_max].
  std::vector<double> v, q, load, T;
  for (int i = 0; i < 61; ++i) {
    v.push_back((i % 2 ? -1.0 : 1.0) * std::pow(10.0, -5.0 + 4.5 * i / 60.0));
    q.push_back(-0.05 + 0.0017 * i);
    load.push_back(-40.0 + 1.3 * i);
    T.push_back(12.0 + 0.75 * i);
  }
  for (double b : {2e-3, -2e-3, 5e-4, -5e-4, 0.0}) {
    v.push_back(b);
    q.push_back(0.005);
    load.push_back(3.0);
    T.push_back(30.0);
  }
  const FeedforwardParams ff{2e-3};
  const FeedbackParams fb{5e-4};
  for (const FrictionLaw& law : {rippled_stribeck(), both}) {
    const bool moves = law.effects().moves_levels();
    SCOPED_TRACE(moves ? "ripple, load and temperature" : "ripple alone");
    const std::string extra = moves ? ", lg[i], tg[i]" : "";
    CExportOptions o;
    o.single_precision = single;
    const std::string arrays = c_array(type.c_str(), "vg", v) + c_array(type.c_str(), "qg", q) +
                               c_array(type.c_str(), "lg", load) + c_array(type.c_str(), "tg", T);
    // The library with the bands as the float header holds them (an edge falls on the same side).
    const FeedforwardCompensation lib_ff(law, FeedforwardParams{as_real(ff.band, single)});
    const FeedbackCompensation lib_fb(law, FeedbackParams{as_real(fb.dead_band, single)});
    std::vector<double> want_ff, want_fb;
    for (std::size_t i = 0; i < v.size(); ++i) {
      CompensatorInput in;
      in.reference = in.position = as_real(q[i], single);
      in.reference_rate = in.velocity = as_real(v[i], single);
      if (moves) {
        in.load = as_real(load[i], single);
        in.temperature = as_real(T[i], single);
      }
      std::vector<double> z(1);
      lib_ff.initial_states(in, z);
      want_ff.push_back(lib_ff.output(in, z));
      lib_fb.initial_states(in, z);
      want_fb.push_back(lib_fb.output(in, z));
    }
    for (const bool feedforward : {true, false}) {
      o.compensation = feedforward ? CompensationParams(ff) : CompensationParams(fb);
      const std::string header = c_header(law, o);
      const std::string fn = feedforward ? "friction_feedforward_at" : "friction_feedback_at";
      EXPECT_THAT(header, ::testing::HasSubstr(fn + "(" + type + (feedforward ? " vr, " : " v, ") + type + " q"));
      TempDir dir;
      const std::vector<double> out = compile_and_run(
          dir, header,
          arrays + "int main(void) {\n  unsigned i;\n  (void)lg; (void)tg;\n"
                   "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)" + fn +
              "(vg[i], qg[i]" + extra + "));\n  return 0;\n}\n");
      expect_close(out, feedforward ? want_ff : want_fb, single, fn);
    }
    // The ripple is in the output (the grid's last point: at rest, q = P/4, inside both bands).
    const double ripple_at_rest = law.ripple(as_real(0.005, single));
    EXPECT_NEAR(want_fb.back(), ripple_at_rest, 1e-12);
    EXPECT_GT(std::abs(ripple_at_rest), 0.5);
  }
}

// A ripple by table (ripple_position, ripple_force over one period): the header's static table
// and its interpolation PREFIX_ripple(q), PREFIX_friction_at(v, q) and the compensations at a
// position, against the library over positions across five periods (both signs), both precisions.
FrictionLaw table_rippled_stribeck() {
  LawEffects e;
  e.ripple = PositionRipple{0.02, {}, {}, {-0.005, 0.0, 0.004, 0.009, 0.015}, {0.3, -0.5, 0.7, 0.1, 0.3}};
  return FrictionLaw(Stribeck{1.0, 1.5, 0.001, 1.0, 0.4}).with_effects(e);
}

TEST_P(RippleExport, TableRippleMatchesLibrary) {
  const bool single = GetParam();
  const FrictionLaw law = table_rippled_stribeck();
  std::vector<double> q, v;
  for (int i = 0; i < 61; ++i) q.push_back(-0.05 + 0.0017 * i + 1e-4 * i * i / 7.0);  // m, across five periods
  for (int i = 0; i < 61; ++i) v.push_back((i % 2 ? -1.0 : 1.0) * std::pow(10.0, -5.0 + 4.5 * i / 60.0));
  for (double row : {-0.005, 0.0, 0.004, 0.009, 0.015, 0.035}) {  // the rows themselves, and a period on
    q.push_back(row);
    v.push_back(0.0);
  }
  CExportOptions o;
  o.single_precision = single;
  const std::string type = single ? "float" : "double";
  const std::string arrays = c_array(type.c_str(), "qg", q) + c_array(type.c_str(), "vg", v);
  {
    TempDir dir;
    const std::string header = c_header(law, o);
    EXPECT_THAT(header, ::testing::HasSubstr("friction_ripple_q[5]"));
    EXPECT_THAT(header, ::testing::HasSubstr("FRICTION_RIPPLE_POINTS 5"));
    const std::vector<double> out = compile_and_run(
        dir, header,
        arrays + "int main(void) {\n  unsigned i;\n"
                 "  for (i = 0; i < sizeof qg / sizeof qg[0]; ++i) printf(\"%.17g\\n\", (double)friction_ripple(qg[i]));\n"
                 "  for (i = 0; i < sizeof qg / sizeof qg[0]; ++i) printf(\"%.17g\\n\", (double)friction_friction_at(vg[i], qg[i]));\n"
                 "  return 0;\n}\n");
    std::vector<double> lib;
    for (double x : q) lib.push_back(law.ripple(as_real(x, single)));
    for (std::size_t i = 0; i < q.size(); ++i) lib.push_back(law.sliding(as_real(v[i], single)) + law.ripple(as_real(q[i], single)));
    expect_close(out, lib, single, "table ripple");
  }
  const FeedforwardParams ff{2e-3};
  const FeedbackParams fb{5e-4};
  const FeedforwardCompensation lib_ff(law, FeedforwardParams{as_real(ff.band, single)});
  const FeedbackCompensation lib_fb(law, FeedbackParams{as_real(fb.dead_band, single)});
  for (const bool feedforward : {true, false}) {
    o.compensation = feedforward ? CompensationParams(ff) : CompensationParams(fb);
    const std::string fn = feedforward ? "friction_feedforward_at" : "friction_feedback_at";
    std::vector<double> want;
    for (std::size_t i = 0; i < v.size(); ++i) {
      CompensatorInput in;
      in.reference = in.position = as_real(q[i], single);
      in.reference_rate = in.velocity = as_real(v[i], single);
      std::vector<double> z(1);
      const Compensator& c = feedforward ? static_cast<const Compensator&>(lib_ff) : lib_fb;
      c.initial_states(in, z);
      want.push_back(c.output(in, z));
    }
    TempDir dir;
    const std::vector<double> out = compile_and_run(
        dir, c_header(law, o),
        arrays + "int main(void) {\n  unsigned i;\n"
                 "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)" + fn +
            "(vg[i], qg[i]));\n  return 0;\n}\n");
    expect_close(out, want, single, fn);
  }
}

// The LuGre observer of a law with a ripple (harmonics, or a table): the header's
// PREFIX_lugre_observer_update adds PREFIX_ripple(x) at the measured position x to the bristle
// copy's force, as the library's LuGreObserver::update does; a fixed-step run over positions across
// several periods, a standstill and a long step, both precisions.
TEST_P(RippleExport, LuGreObserverAddsTheRippleAsTheLibrary) {
  const bool single = GetParam();
  const std::string type = single ? "float" : "double";
  std::vector<double> x, v, r, dt;
  double pos = -0.013;
  for (int k = 0; k < 600; ++k) {
    const double vel = 0.05 * std::sin(0.01 * k) + (k > 400 && k < 450 ? -0.05 : 0.0);  // m/s
    const double vk = k > 500 && k < 560 ? 0.0 : vel;                                  // a standstill
    pos += vk * 1e-3;
    x.push_back(pos);
    v.push_back(vk);
    r.push_back(pos + 2e-5 * std::cos(0.03 * k));
    dt.push_back(k == 599 ? 5.0 : 1e-3);
  }
  const std::string arrays = c_array(type.c_str(), "x", x) + c_array(type.c_str(), "v", v) +
                             c_array(type.c_str(), "r", r) + c_array(type.c_str(), "dt", dt);
  LawEffects harmonics, table;
  harmonics.ripple = PositionRipple{0.02, {0.6, 0.15}, {-0.4, 0.0}, {}, {}};
  table.ripple = PositionRipple{0.02, {}, {}, {0.0, 0.005, 0.012, 0.02}, {0.2, -0.6, 0.5, 0.2}};
  for (const LawEffects* e : {&harmonics, &table}) {
    SCOPED_TRACE(e == &table ? "table" : "harmonics");
    const FrictionLaw law = FrictionLaw(LuGre{}).with_effects(*e);
    const LuGreObserverParams p{0.05};
    CExportOptions o;
    o.single_precision = single;
    o.compensation = p;
    const std::string header = c_header(law, o);
    EXPECT_THAT(header, ::testing::HasSubstr("+ friction_ripple(x)"));
    TempDir dir;
    const std::vector<double> out = compile_and_run(
        dir, header,
        arrays + "int main(void) {\n  unsigned i;\n  friction_lugre_observer_state s;\n"
                 "  friction_lugre_observer_init(&s, v[0]);\n"
                 "  for (i = 0; i < sizeof v / sizeof v[0]; ++i)\n"
                 "    printf(\"%.17g\\n\", (double)friction_lugre_observer_update(&s, x[i], v[i], r[i], dt[i]));\n"
                 "  return 0;\n}\n");
    const LuGreObserver obs(law, p), plain(LuGre{}, p);
    double z = 0, z_plain = 0;
    std::vector<double> lib;
    CompensatorInput in0;
    in0.velocity = as_real(v[0], single);
    obs.initial_states(in0, {&z, 1});
    plain.initial_states(in0, {&z_plain, 1});
    double largest = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
      CompensatorInput in;
      in.position = as_real(x[k], single);
      in.velocity = as_real(v[k], single);
      in.reference = as_real(r[k], single);
      lib.push_back(obs.update(in, {&z, 1}, as_real(dt[k], single)));
      // The library's observer is the plain one's bristle copy plus r(x): the ripple leaves the
      // observer's state alone and adds at the measured position.
      const double bristles = plain.update(in, {&z_plain, 1}, as_real(dt[k], single));
      EXPECT_EQ(z, z_plain);
      EXPECT_NEAR(lib.back(), bristles + law.ripple(in.position), 1e-12 * (1 + std::abs(bristles)));
      largest = std::max(largest, std::abs(law.ripple(in.position)));
    }
    EXPECT_GT(largest, 0.3);  // N: the run crosses the ripple's peaks
    expect_close(out, lib, single, "lugre-observer with a ripple");
  }
}

INSTANTIATE_TEST_SUITE_P(BothPrecisions, RippleExport, ::testing::Bool());

// Load and temperature terms: the header's PREFIX_friction_at(v[, q][, load][, T]), its
// breakaway levels at the conditions and the feedforward and feedback at a measured load and
// temperature, against the library's sliding(v, c) + ripple(q), breakaway_positive(c) and
// FeedforwardCompensation / FeedbackCompensation::force(v, c), both precisions, to expect_close's
// tolerances (kRelTol, kFloatTol: the same formulas in the same order as the plain laws').
class EffectsExport : public ::testing::TestWithParam<bool> {};

struct EffectsGrid {
  std::vector<double> v, q, load, T;
};

EffectsGrid effects_grid() {
  EffectsGrid g;
  for (int i = 0; i < 37; ++i) {
    g.v.push_back((i % 2 ? -1.0 : 1.0) * std::pow(10.0, -5.0 + 5.5 * i / 36.0));  // m/s, both signs
    g.q.push_back(-0.05 + 0.0027 * i);                                           // m, across five periods
    g.load.push_back(-40.0 + 2.3 * i);                                           // N, both signs
    g.T.push_back(12.0 + 1.3 * i);                                               // degC, in [T_min, T_max]
  }
  return g;
}

std::string grid_arrays(const EffectsGrid& g, const std::string& type) {
  return c_array(type.c_str(), "vg", g.v) + c_array(type.c_str(), "qg", g.q) + c_array(type.c_str(), "lg", g.load) +
         c_array(type.c_str(), "tg", g.T);
}

Conditions at(const EffectsGrid& g, std::size_t i, bool single) {
  Conditions c;
  c.load = as_real(g.load[i], single);
  c.temperature = as_real(g.T[i], single);
  c.position = as_real(g.q[i], single);
  return c;
}

TEST_P(EffectsExport, FrictionAtAndBreakawayAtMatchLibraryWithLoadTemperatureAndRipple) {
  const bool single = GetParam();
  LawEffects e = load_and_temperature(true);
  e.ripple = PositionRipple{0.02, {0.6, 0.15}, {-0.4, 0.0}, {}, {}};
  const FrictionLaw law = FrictionLaw(Stribeck{1.0, 1.5, 0.001, 1.0, 0.4}).with_effects(e);
  const EffectsGrid g = effects_grid();
  TempDir dir;
  CExportOptions o;
  o.single_precision = single;
  const std::string type = single ? "float" : "double";
  const std::string header = c_header(law, o);
  EXPECT_THAT(header, ::testing::HasSubstr("friction_friction_at(" + type + " v, " + type + " q, " + type + " load, " +
                                           type + " T)"));
  EXPECT_THAT(header, ::testing::HasSubstr("`load` in N (N m on a rotary axis)"));
  const std::vector<double> out = compile_and_run(
      dir, header,
      grid_arrays(g, type) +
          "int main(void) {\n  unsigned i;\n"
          "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)friction_friction_at(vg[i], qg[i], lg[i], tg[i]));\n"
          "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)friction_breakaway_pos_at(lg[i], tg[i]));\n"
          "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)friction_breakaway_neg_at(lg[i], tg[i]));\n"
          "  return 0;\n}\n");
  std::vector<double> lib;
  for (std::size_t i = 0; i < g.v.size(); ++i)
    lib.push_back(law.sliding(as_real(g.v[i], single), at(g, i, single)) + law.ripple(as_real(g.q[i], single)));
  for (std::size_t i = 0; i < g.v.size(); ++i) lib.push_back(law.breakaway_positive(at(g, i, single)));
  for (std::size_t i = 0; i < g.v.size(); ++i) lib.push_back(law.breakaway_negative(at(g, i, single)));
  expect_close(out, lib, single, "stribeck with load, temperature and ripple");
  // The load and temperature do move the force (a test that would pass with the terms ignored is none).
  EXPECT_GT(std::abs(law.sliding(0.1, at(g, 0, false)) - law.sliding(0.1)), 1.0);
}

TEST_P(EffectsExport, ArgumentsFollowTheTermsAndCompensationsTakeLoadAndTemperature) {
  const bool single = GetParam();
  const std::string type = single ? "float" : "double";
  const EffectsGrid g = effects_grid();
  // Load only, asymmetric Stribeck: friction_at(v, load), feedforward_at(vr, load).
  {
    LawEffects e;
    e.load = LoadDependence{0.07, 0.05};
    const FrictionLaw law = FrictionLaw(Asymmetric<Stribeck>{Stribeck{1.0, 1.5, 0.001, 1.0, 0.4},
                                                             Stribeck{0.8, 1.1, 0.002, 2.0, 0.5}})
                                .with_effects(e);
    CExportOptions o;
    o.single_precision = single;
    o.compensation = FeedforwardParams{2e-3};
    TempDir dir;
    const std::vector<double> out = compile_and_run(
        dir, c_header(law, o),
        grid_arrays(g, type) +
            "int main(void) {\n  unsigned i;\n  (void)qg; (void)tg;\n"
            "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)friction_friction_at(vg[i], lg[i]));\n"
            "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)friction_feedforward_at(vg[i] * 1e-2, lg[i]));\n"
            "  return 0;\n}\n");
    const FeedforwardCompensation ff(law, FeedforwardParams{2e-3});
    std::vector<double> lib;
    for (std::size_t i = 0; i < g.v.size(); ++i) lib.push_back(law.sliding(as_real(g.v[i], single), at(g, i, single)));
    for (std::size_t i = 0; i < g.v.size(); ++i)
      lib.push_back(ff.force(as_real(as_real(g.v[i], single) * 1e-2, single), at(g, i, single)));
    expect_close(out, lib, single, "asymmetric stribeck with load, feedforward");
  }
  // Temperature only, coulomb-viscous with feedback: friction_at(v, T), feedback_at(v, T).
  {
    LawEffects e = load_and_temperature(false);
    e.load.reset();
    const FrictionLaw law = FrictionLaw(CoulombViscous{1.0, 0.4}).with_effects(e);
    CExportOptions o;
    o.single_precision = single;
    o.compensation = FeedbackParams{1e-3};
    TempDir dir;
    const std::string header = c_header(law, o);
    EXPECT_THAT(header, ::testing::HasSubstr("friction_friction_at(" + type + " v, " + type + " T)"));
    const std::vector<double> out = compile_and_run(
        dir, header,
        grid_arrays(g, type) +
            "int main(void) {\n  unsigned i;\n  (void)qg; (void)lg;\n"
            "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)friction_friction_at(vg[i], tg[i]));\n"
            "  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%.17g\\n\", (double)friction_feedback_at(vg[i], tg[i]));\n"
            "  return 0;\n}\n");
    const FeedbackCompensation fb(law, FeedbackParams{1e-3});
    std::vector<double> lib;
    for (std::size_t i = 0; i < g.v.size(); ++i) lib.push_back(law.sliding(as_real(g.v[i], single), at(g, i, single)));
    for (std::size_t i = 0; i < g.v.size(); ++i) lib.push_back(fb.force(as_real(g.v[i], single), at(g, i, single)));
    expect_close(out, lib, single, "coulomb-viscous with temperature, feedback");
  }
}

INSTANTIATE_TEST_SUITE_P(BothPrecisions, EffectsExport, ::testing::Bool());

// A constant the header's type cannot hold is refused with the code output.not_finite (error.hpp):
// float would hold 1e39 as inf, and a bristle rate sigma0 / Fc of 1e39 overflows float at a
// finite speed.
TEST(CExportErrors, ConstantsBeyondTheTypeAreOutputNotFinite) {
  CExportOptions o;
  o.single_precision = true;
  auto code_of = [&](const FrictionLaw& law) -> std::string {
    try {
      c_header(law, o);
    } catch (const InputError& e) {
      return e.code();
    } catch (const std::exception& e) {
      return std::string("not an InputError: ") + e.what();
    }
    return "no error";
  };
  EXPECT_EQ(code_of(Coulomb{1e39}), "output.not_finite");
  LuGre stiff;
  stiff.sigma0 = 1e39;
  EXPECT_EQ(code_of(stiff), "output.not_finite");
  o.single_precision = false;
  EXPECT_EQ(code_of(Coulomb{1e39}), "no error");  // double holds it
}

TEST(CExportErrors, DynamicLawWithLoadIsRefusedSayingWhy) {
  using testing::error_of;
  LawEffects load;
  load.load = LoadDependence{0.05, 0.05};
  EXPECT_THAT(error_of([&] { c_header(FrictionLaw(LuGre{}).with_effects(load)); }),
              ::testing::HasSubstr("the header's state update runs on fixed levels"));
  EXPECT_THAT(error_of([&] { c_header(FrictionLaw(LuGre{}).with_effects(load)); }), ::testing::HasSubstr("mu_load"));
  CExportOptions o;
  o.compensation = LuGreObserverParams{};
  EXPECT_THAT(error_of([&] { c_header(FrictionLaw(LuGre{}).with_effects(load), o); }),
              ::testing::HasSubstr("mu_load"));
}

}  // namespace
}  // namespace frictionlab
