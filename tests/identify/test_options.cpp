// The option tables of the identification methods (identify/options.hpp, identify/method.hpp):
// each method's defaults are its options struct's (one source), the checks name the option, the
// value and what was expected, the reference lists every option as the table says, and the
// registry holds every method once, in its order.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "../error_message.hpp"
#include "frictionlab/identify/breakaway.hpp"
#include "frictionlab/identify/decay.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/identify/method.hpp"
#include "frictionlab/identify/option_applies.hpp"
#include "frictionlab/identify/sweep.hpp"

namespace frictionlab {
namespace {

using testing::error_of;

TEST(Options, RegistryHoldsEveryMethodOnceInItsOrder) {
  const std::vector<std::string> want = {"idim", "breakaway", "sweep", "decay", "lugre", "auto", "validate"};
  ASSERT_EQ(identification_methods().size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    const MethodInfo& m = identification_methods()[i];
    EXPECT_EQ(m.name, want[i]);
    EXPECT_EQ(&method_info(m.id), &m) << m.name;
    EXPECT_EQ(&method_info(m.name), &m) << m.name;
    std::set<std::string> names, keywords;
    for (const auto& o : m.options) {
      EXPECT_TRUE(names.insert(o.name).second) << m.name << ": option " << o.name << " twice";
      EXPECT_TRUE(keywords.insert(o.keyword()).second) << m.name << ": keyword " << o.keyword() << " twice";
      EXPECT_FALSE(o.help.empty()) << m.name << " --" << o.name;
      for (const auto& old : o.deprecated_keywords) EXPECT_TRUE(keywords.insert(old).second) << old;
    }
  }
  EXPECT_EQ(method_info(MethodId::automatic).name, "auto");  // a keyword as a name: its enumerator is spelled out
  EXPECT_EQ(method_info(MethodId::sweep).name, "sweep");
}

// The table's defaults are the struct's: options made from no values equal a default struct.
TEST(Options, DefaultsComeFromTheOptionsStructs) {
  {
    const SweepOptions t = make_sweep_options(method_info(MethodId::sweep).values()), d;
    EXPECT_EQ(t.fit.model, d.fit.model);
    EXPECT_EQ(t.fit.fixed_delta, d.fit.fixed_delta);
    EXPECT_EQ(t.relative_tolerance, d.relative_tolerance);
    EXPECT_EQ(t.velocity_tolerance, d.velocity_tolerance);
    EXPECT_EQ(t.noise_band, d.noise_band);
    EXPECT_EQ(t.smoothing_fraction, d.smoothing_fraction);
    EXPECT_EQ(t.min_duration, d.min_duration);
    EXPECT_EQ(t.settle_fraction, d.settle_fraction);
    EXPECT_EQ(t.min_speed, d.min_speed);  // computed from the data: the struct's "not given"
    EXPECT_EQ(t.min_segments, d.min_segments);
    EXPECT_TRUE(t.windows.empty());
  }
  {
    const BreakawayOptions t = make_breakaway_options(method_info(MethodId::breakaway).values()), d;
    EXPECT_TRUE(std::isnan(t.inertia) && std::isnan(d.inertia));
    EXPECT_TRUE(std::isnan(t.velocity_threshold) && std::isnan(d.velocity_threshold));
    EXPECT_EQ(t.edge_samples, d.edge_samples);
  }
  {
    const DecayOptions t = make_decay_options(method_info(MethodId::decay).values()), d;
    EXPECT_TRUE(std::isnan(t.stiffness) && std::isnan(t.inertia) && std::isnan(t.natural_frequency));
    EXPECT_EQ(t.pendulum, d.pendulum);
    EXPECT_TRUE(std::isnan(t.stop_threshold) && std::isnan(d.stop_threshold));
  }
  {
    OptionValues v = method_info(MethodId::lugre).values();
    v.set("inertia", 2.0, "--inertia");  // required: no default
    const LugreOptions t = make_lugre_options(v), d;
    EXPECT_EQ(t.inertia, 2.0);
    EXPECT_EQ(t.delta, d.delta);
    EXPECT_EQ(t.stribeck_velocity, d.stribeck_velocity);
    EXPECT_EQ(t.vd, d.vd);
    EXPECT_EQ(t.substeps, d.substeps);
    EXPECT_EQ(t.max_iterations, d.max_iterations);
  }
  {
    const IdimOptions t = make_idim_options(method_info(MethodId::idim).values()), d;
    EXPECT_EQ(t.terms, d.terms);
    EXPECT_EQ(t.cutoff_hz, d.cutoff_hz);
    EXPECT_EQ(t.filter_order, d.filter_order);
    EXPECT_EQ(t.padlen, d.padlen);
    EXPECT_EQ(t.decimation, d.decimation);
    EXPECT_EQ(t.skip, d.skip);
    EXPECT_EQ(t.skip_end, d.skip_end);
    EXPECT_EQ(t.stribeck_vs, d.stribeck_vs);
    EXPECT_EQ(t.search_stribeck_vs, d.search_stribeck_vs);
    EXPECT_EQ(t.stribeck_delta, d.stribeck_delta);
    EXPECT_EQ(t.input_delay, d.input_delay);
    EXPECT_EQ(t.min_velocity, d.min_velocity);
    EXPECT_EQ(t.max_condition, d.max_condition);
    EXPECT_EQ(t.source, d.source);
    // Not given: taken from the sample rate, as the command line always did.
    EXPECT_TRUE(t.auto_cutoff && t.auto_decimation && t.auto_skip);
  }
}

TEST(Options, GivenValuesReachTheStruct) {
  OptionValues v = method_info(MethodId::idim).values();
  const MethodInfo& idim = method_info(MethodId::idim);
  v.set("vs", parse_option(*idim.option("vs"), "search", "--vs"), "--vs");
  v.set("terms", parse_option(*idim.option("terms"), "inertia,asymmetric,stribeck", "--terms"), "--terms");
  v.set("decimate", 5LL, "--decimate");
  const IdimOptions o = make_idim_options(v);
  EXPECT_TRUE(o.search_stribeck_vs);
  EXPECT_EQ(o.terms, (std::vector<std::string>{"inertia", "asymmetric", "stribeck"}));
  EXPECT_EQ(o.decimation, 5);
  EXPECT_FALSE(o.auto_decimation);
  EXPECT_TRUE(o.auto_cutoff);

  OptionValues s = method_info(MethodId::sweep).values();
  s.set("segment", std::vector<std::string>{"1:1.9"}, "--segment");
  s.set("segment", std::vector<std::string>{"5.5:6"}, "--segment");  // repeatable: one item each time
  const SweepOptions so = make_sweep_options(s);
  ASSERT_EQ(so.windows.size(), 2u);
  EXPECT_EQ(so.windows[1].t_begin, 5.5);
  EXPECT_EQ(so.windows[1].t_end, 6.0);
}

TEST(Options, ChecksNameTheOptionTheValueAndWhatWasExpected) {
  const MethodInfo& sweep = method_info(MethodId::sweep);
  EXPECT_EQ(error_of([&] { parse_option(*sweep.option("min-duration"), "-1", "--min-duration"); }),
            "--min-duration = -1 must be > 0 (s)");
  EXPECT_EQ(error_of([&] { parse_option(*sweep.option("min-duration"), "abc", "--min-duration"); }),
            "--min-duration 'abc': expected a number > 0 (s)");
  EXPECT_EQ(error_of([&] { parse_option(*sweep.option("model"), "lugre", "--model"); }),
            "--model 'lugre' cannot be fitted to a friction-velocity map; expected coulomb-viscous, "
            "coulomb-viscous-asymmetric, stribeck or stribeck-asymmetric");
  EXPECT_EQ(error_of([&] { parse_option(*sweep.option("velocity-tolerance"), "nan", "--velocity-tolerance"); }),
            "--velocity-tolerance = nan must be finite and >= 0 (m/s or rad/s)");
  const MethodInfo& idim = method_info(MethodId::idim);
  EXPECT_EQ(error_of([&] { parse_option(*idim.option("vs"), "fast", "--vs"); }),
            "--vs 'fast': expected a Stribeck velocity (m/s or rad/s) or 'search'");
  EXPECT_EQ(error_of([&] { check_option(*idim.option("decimate"), 0LL, "idim: decimation"); }),
            "idim: decimation = 0 must be >= 1");
  EXPECT_EQ(error_of([&] { check_option(*idim.option("decimate"), 2.5, "idim: decimate"); }),
            "idim: decimate 2.5: expected an integer >= 1");
  EXPECT_EQ(error_of([&] { check_option(*idim.option("from"), std::string("force"), "--from"); }),
            "--from 'force': expected position or velocity");
  OptionValues v = sweep.values();
  EXPECT_EQ(error_of([&] { v.set("bogus", 1.0, "--bogus"); }).rfind("option 'bogus' is not known; expected one of model, ", 0),
            0u);
  // A bad --segment names the flag and the form expected.
  v.set("segment", std::vector<std::string>{"2.5-4"}, "--segment");
  EXPECT_EQ(error_of([&] { make_sweep_options(v); }), "--segment '2.5-4': expected T_BEGIN:T_END in seconds, e.g. 2.5:4.0");
}

// IDIM-IV's gains take a number or the name of a scalar of the data file (kept as text for the
// method to resolve); what is neither a number nor a name is still refused.
TEST(Options, GainsTakeTheNameOfAScalarOfTheDataFile) {
  const OptionSpec& kp = *method_info(MethodId::idim).option("kp");
  EXPECT_EQ(std::get<std::string>(parse_option(kp, "Kp", "--kp")), "Kp");
  EXPECT_EQ(std::get<std::string>(check_option(kp, std::string("gain_1"), "idim: kp")), "gain_1");
  EXPECT_EQ(std::get<double>(parse_option(kp, "160.18", "--kp")), 160.18);
  EXPECT_EQ(error_of([&] { parse_option(kp, "-5", "--kp"); }).rfind("--kp = -5 must be >= 0 (", 0), 0u);
  EXPECT_EQ(error_of([&] { parse_option(kp, "1e3x", "--kp"); })
                .rfind("--kp '1e3x': expected a number >= 0 or the name of a scalar of the data file (", 0),
            0u);
  // Not for options that take numbers only.
  EXPECT_EQ(error_of([&] { parse_option(*method_info(MethodId::idim).option("cutoff"), "fc", "--cutoff"); }),
            "--cutoff 'fc': expected a number > 0 (Hz)");
}

// The record of a result: every option of the table with its value, unit on the axis, and whether given.
TEST(Options, RecordListsEveryOptionWithValueAndUnit) {
  const MethodInfo& sweep = method_info(MethodId::sweep);
  OptionValues v = sweep.values();
  v.set("min-duration", 1.5, "--min-duration");
  const auto j = nlohmann::json::parse(options_json(v, true));
  ASSERT_EQ(j.size(), sweep.options.size());
  EXPECT_EQ(j["min-duration"]["value"], 1.5);
  EXPECT_EQ(j["min-duration"]["unit"], "s");
  EXPECT_EQ(j["min-duration"]["given"], true);
  EXPECT_EQ(j["model"]["value"], "stribeck");
  EXPECT_EQ(j["model"]["given"], false);
  EXPECT_EQ(j["velocity-tolerance"]["unit"], "rad/s");  // rotary
  EXPECT_TRUE(j["min-speed"]["value"].is_null());      // computed from the data
  EXPECT_EQ(nlohmann::json::parse(options_json(v, false))["velocity-tolerance"]["unit"], "m/s");
}

// A unit that another option decides (OptionSpec::units) is the run's: --kp is N/m (N m/rad) with
// --controller pid, 1/s with emps-pd, and with the controller a scenario gave, which the result
// records (iv_controller_type); only where nothing decides it does it name every case. The help
// and the reference name each case with its condition. No table writes "X or Y" as a plain unit
// other than where the run's choices cannot decide it (the temperature column's degC or K).
TEST(Options, UnitThatAnOptionDecidesIsTheRuns) {
  const MethodInfo& idim = method_info(MethodId::idim);
  OptionValues v = idim.values();
  EXPECT_EQ(v.unit("kp", false), "N/m or 1/s");  // nothing decides it
  EXPECT_EQ(v.unit("kp", true), "N m/rad or 1/s");
  EXPECT_EQ(idim.option("kp")->unit_text(), "N/m or N m/rad with pid, 1/s with emps-pd");
  EXPECT_EQ(idim.option("control-limit")->unit_text(), "N or N m with pid, V with emps-pd");
  v.set("controller", std::string("emps-pd"), "--controller");
  EXPECT_EQ(v.unit("kp", false), "1/s");
  EXPECT_EQ(v.unit("kp", true), "1/s");
  EXPECT_EQ(v.unit("control-limit", true), "V");
  EXPECT_EQ(v.unit("kv", false), "V s/m");  // a plain unit is unchanged
  v.set("controller", std::string("pid"), "--controller");
  EXPECT_EQ(v.unit("kp", false), "N/m");
  EXPECT_EQ(v.unit("kp", true), "N m/rad");
  EXPECT_EQ(v.unit("control-limit", false), "N");
  // Not given: the controller the run took from its scenario, as the result records it.
  const OptionValues scenario = idim.values();
  const std::map<std::string, std::string> texts = {{"iv_controller_type", "emps-pd"}};
  EXPECT_EQ(scenario.unit("kp", false, texts), "1/s");
  EXPECT_EQ(nlohmann::json::parse(options_json(scenario, false, texts))["kp"]["unit"], "1/s");
  EXPECT_EQ(nlohmann::json::parse(options_json(v, true))["kp"]["unit"], "N m/rad");

  for (const auto& m : identification_methods())
    for (const auto& o : m.options) {
      for (const auto& u : o.units) {
        EXPECT_NE(m.option(u.when.option), nullptr) << m.name << " --" << o.name << ": " << u.when.option;
        EXPECT_TRUE(o.unit.empty() && o.rotary_unit.empty()) << m.name << " --" << o.name << ": units and unit both";
      }
      const bool undecided = o.name == "temperature" || o.name == "temperature-ref";
      if (!undecided)
        EXPECT_EQ(o.unit.find(" or "), std::string::npos) << m.name << " --" << o.name << ": '" << o.unit
                                                          << "': give `units` with the option that decides it";
    }
}

// When an option applies (OptionSpec::applies_if, which the report's Options table follows): an
// IV option only with --iv, the Stribeck term's only when --terms holds stribeck, sweep's
// detection options not with --segment; every condition names an option of its own table.
TEST(Options, AppliesFollowsTheTableConditions) {
  const MethodInfo& idim = method_info(MethodId::idim);
  OptionValues v = idim.values();
  EXPECT_TRUE(v.applies("filter-order"));  // no condition: always
  EXPECT_FALSE(v.applies("iv-iterations"));
  EXPECT_FALSE(v.applies("kp"));
  EXPECT_FALSE(v.applies("vs"));  // the default terms have no stribeck
  v.set("iv", true, "--iv");
  v.set("terms", parse_option(*idim.option("terms"), "inertia,viscous,coulomb,stribeck", "--terms"), "--terms");
  EXPECT_TRUE(v.applies("iv-iterations"));
  EXPECT_TRUE(v.applies("kp"));
  EXPECT_TRUE(v.applies("vs"));
  EXPECT_FALSE(v.applies("ripple-harmonics"));
  OptionValues off = idim.values();
  off.set("iv", false, "iv");  // given, but off (Python iv=False)
  EXPECT_FALSE(off.applies("iv-tolerance"));

  const MethodInfo& sweep = method_info(MethodId::sweep);
  OptionValues s = sweep.values();
  EXPECT_TRUE(s.applies("delta"));  // the default model is stribeck
  EXPECT_TRUE(s.applies("noise-band"));
  s.set("model", std::string("coulomb-viscous"), "--model");
  s.set("reference", std::string("v_cmd"), "--reference");
  EXPECT_FALSE(s.applies("delta"));
  EXPECT_FALSE(s.applies("noise-band"));  // found on the reference: no noise band
  EXPECT_TRUE(s.applies("min-duration"));
  s.set("segment", std::vector<std::string>{"1:2"}, "--segment");
  EXPECT_FALSE(s.applies("min-duration"));

  for (const auto& m : identification_methods()) {
    const OptionValues defaults = m.values();
    for (const auto& o : m.options) {
      for (const auto& c : o.applies_if) EXPECT_NE(m.option(c.option), nullptr) << m.name << " --" << o.name << ": " << c.option;
      EXPECT_NO_THROW(defaults.applies(o.name)) << m.name << " --" << o.name;
    }
  }
}

// When an option applies is said in words from its table's conditions, as `identify METHOD
// --help` and the reference (docs/options.md) print it.
TEST(Options, AppliesTextSaysTheConditions) {
  const MethodInfo& idim = method_info(MethodId::idim);
  EXPECT_EQ(applies_text(*idim.option("filter-order"), idim.options), "");  // always
  EXPECT_EQ(applies_text(*idim.option("kp"), idim.options), "applies with --iv");
  EXPECT_EQ(applies_text(*idim.option("vs"), idim.options), "applies when --terms holds stribeck");  // a list
  const MethodInfo& sweep = method_info(MethodId::sweep);
  EXPECT_EQ(applies_text(*sweep.option("delta"), sweep.options),
            "applies when --model is stribeck or stribeck-asymmetric");  // a text
  EXPECT_EQ(applies_text(*sweep.option("noise-band"), sweep.options),
            "applies without --segment and without --reference");
  EXPECT_EQ(applies_text(*idim.option("kp"), idim.options, AppliesStyle::markdown), "applies with `--iv`");
  // The docstrings' wording: Python keywords, a flag True or False, words as Python strings.
  EXPECT_EQ(applies_text(*idim.option("kp"), idim.options, AppliesStyle::python), "applies with iv=True");
  EXPECT_EQ(applies_text(*idim.option("vs"), idim.options, AppliesStyle::python), "applies when terms holds 'stribeck'");
  EXPECT_EQ(applies_text(*sweep.option("noise-band"), sweep.options, AppliesStyle::python),
            "applies when segment is not given and when reference is not given");
  OptionSpec lost;
  lost.name = "x";
  lost.applies_if = {when_given("no-such-option")};
  EXPECT_EQ(error_of([&] { applies_text(lost, idim.options); }),
            "--x: its condition names --no-such-option, which is not an option of the table");
  // Every conditional option of every table says when it applies in the reference.
  const std::string md = options_markdown();
  for (const auto& m : identification_methods())
    for (const auto& o : m.options)
      if (!o.applies_if.empty()) {
        const std::size_t section = md.find("\n## " + m.name + "\n");  // idim and sweep both have --delta
        const std::size_t row = md.find("| `--" + o.name + "` | `" + o.keyword() + "` | ", section);
        ASSERT_NE(row, std::string::npos) << m.name << " --" << o.name;
        EXPECT_NE(md.substr(row, md.find('\n', row) - row).find("(" + applies_text(o, m.options, AppliesStyle::markdown) + ")"),
                  std::string::npos)
            << m.name << " --" << o.name;
      }
}

// The reference is what the tables say: a heading per method and a row per option with its
// flag, keyword, default and valid values.
TEST(Options, MarkdownReferenceListsEveryOptionOfEveryTable) {
  const std::string md = options_markdown();
  for (const auto& m : identification_methods()) {
    EXPECT_NE(md.find("\n## " + m.name + "\n"), std::string::npos) << m.name;
    for (const auto& o : m.options) {
      const std::string row = "| `--" + o.name + "` | `" + o.keyword() + "` | ";
      EXPECT_NE(md.find(row), std::string::npos) << m.name << ": " << row;
    }
  }
  // The sweep's min-speed default is computed (1e-6 of the largest |velocity|), as the library does.
  EXPECT_NE(md.find("| `--min-speed` | `min_speed` | number | m/s or rad/s | computed |"), std::string::npos);
  EXPECT_NE(md.find("1e-6 of the largest \\|velocity\\|"), std::string::npos);  // a cell escapes |
  EXPECT_NE(md.find("| `--vs` | `vs` | number | m/s or rad/s | `0.01` |"), std::string::npos);
  EXPECT_NE(md.find("(Python, deprecated: `stribeck_vs`)"), std::string::npos);
}

// identify_sweep checks its time column like every method: irregular time names the sample.
TEST(Options, SweepRefusesIrregularTimeLikeEveryMethod) {
  const int n = 400;
  SweepData d{Eigen::VectorXd(n), Eigen::VectorXd::Constant(n, 1.0), Eigen::VectorXd::Constant(n, 0.5), {}};
  for (int i = 0; i < n; ++i) d.time[i] = 0.01 * i;
  d.time[200] = 2.0095;  // half a step late: more than 1 % of the median step off
  const std::string msg = error_of([&] { identify_sweep(d, {}); });
  EXPECT_EQ(msg.rfind("sweep: sample ", 0), 0u) << msg;
  EXPECT_NE(msg.find("regularly sampled"), std::string::npos) << msg;
}

}  // namespace
}  // namespace frictionlab
