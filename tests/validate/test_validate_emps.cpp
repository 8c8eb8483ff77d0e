// Closed-loop validation on the EMPS benchmark (data/emps): the symmetric IDIM-LS estimates
// simulated in the benchmark's PD loop (examples/emps_closed_loop.yaml), against the published
// closed-loop simulation errors (Janot, Gautier, Brunot 2019).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/validate.hpp"
#include "frictionlab/identify/idim_record.hpp"
#include "frictionlab/io/mat.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/emps_pd_loop.hpp"

namespace fl = frictionlab;

namespace {

// Acceptance rule of the issue: position and velocity errors no worse than the published ones
// by more than 10 %.
constexpr double kPublishedMargin = 1.1;
// Acceleration and force are only loosely checked: the published simulation's details (solver,
// which force it compared) are not documented; our controller force is the drive input the
// simulated loop computed, which amplifies micrometre position differences by
// kp kv gtau = 1.4e6 N/m. Within a factor 3 of the published figure.
constexpr double kLooseFactor = 3.0;

struct Published {
  double position, velocity, acceleration, force;
};

std::shared_ptr<const fl::Dataset> load(const std::string& name) {
  return std::make_shared<const fl::Dataset>(fl::read_mat(std::string(FRICTIONLAB_DATA_DIR) + "/emps/" + name));
}

fl::IdimData idim_data(const fl::Dataset& d) { return fl::idim_record(d, {"t", "qm", "vir", "gtau"}); }

fl::Result run(const fl::IdentifiedModel& model, const std::shared_ptr<const fl::Dataset>& d) {
  fl::ScenarioOptions so;
  so.data = d;
  so.law = model.law;
  so.axis = model.axis;
  const fl::Scenario sc = fl::load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/emps_closed_loop.yaml", so);
  const fl::IdimData x = idim_data(*d);
  fl::ValidationData v{x.time, x.position, x.force, x.file, x.sha256};
  return fl::validate_model(model, sc, v);
}

void check(const fl::Result& r, const Published& p, const char* file) {
  ASSERT_TRUE(r.validation.has_value());
  const auto& e = r.validation->signal_errors_percent;
  const auto& full = r.diagnostics.groups.at("relative_error_percent_full_rate");
  std::printf("%s: relative errors %% (ours on the IDIM grid / full rate / published)\n", file);
  const char* names[] = {"position", "velocity", "acceleration", "force"};
  const double pub[] = {p.position, p.velocity, p.acceleration, p.force};
  for (int i = 0; i < 4; ++i)
    std::printf("  %-12s %9.4f %9.4f %9.4f\n", names[i], e.at(names[i]), full.at(names[i]), pub[i]);
  EXPECT_LE(e.at("position"), kPublishedMargin * p.position);
  EXPECT_LE(e.at("velocity"), kPublishedMargin * p.velocity);
  EXPECT_LE(e.at("acceleration"), kLooseFactor * p.acceleration);
  EXPECT_LE(e.at("force"), kLooseFactor * p.force);
  for (const char* s : {"time", "position", "position_sim", "velocity", "velocity_sim", "force", "force_sim"})
    EXPECT_EQ(r.series.at(s).size(), r.series.at("time").size()) << s;
}

}  // namespace

class ValidateEmps : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ident_ = load("DATA_EMPS.mat");
    pulses_ = load("DATA_EMPS_PULSES.mat");
    const fl::Result identified = fl::identify_idim(idim_data(*ident_));
    ASSERT_TRUE(identified.ok()) << identified.message;
    model_ = new fl::IdentifiedModel(fl::model_from_result(identified));
  }
  static void TearDownTestSuite() {
    delete model_;
    model_ = nullptr;
  }
  static inline std::shared_ptr<const fl::Dataset> ident_, pulses_;
  static inline fl::IdentifiedModel* model_ = nullptr;
};

TEST_F(ValidateEmps, IdentificationDataMatchesPublished) {
  check(run(*model_, ident_), {0.0138, 0.229, 8.60, 5.85}, "DATA_EMPS.mat");
}

TEST_F(ValidateEmps, PulsesDataMatchesPublished) {
  check(run(*model_, pulses_), {0.0080, 0.479, 19.8, 8.94}, "DATA_EMPS_PULSES.mat");
}
