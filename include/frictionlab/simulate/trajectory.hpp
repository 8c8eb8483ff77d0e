#pragma once
// The result of a simulation: sampled signals as columns, plus the mode switches that happened.

#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// What kind of mode switch an event was (hybrid mode).
enum class SwitchKind {
  breakaway,  ///< stuck -> sliding: |applied| reached the breakaway level
  stick,      ///< sliding -> stuck: velocity reached 0 and |applied| is within the breakaway levels
  reversal,   ///< velocity reached 0 and |applied| exceeds the breakaway level on the other side
  impact,     ///< an impact of the plant (a backlash flank) set the velocity of a stuck body, or
              ///< reversed a sliding one's
};

/// One mode switch, at the exact time the root finder located.
struct ModeSwitch {
  double time = 0.0;      ///< s
  SwitchKind kind = SwitchKind::stick;
  double position = 0.0;  ///< m or rad
  double applied = 0.0;   ///< applied force at the switch (N or N m)
  int direction = 0;      ///< sliding direction after the switch (+1 / -1), 0 when stuck
  int contact = 0;        ///< the contact that switched (Plant::contact index; 0 for a 1-DOF plant)
};

/// One of the plant's own events (Plant::events), at the time the root finder located it.
struct PlantEvent {
  double time = 0.0;  ///< s
  int index = 0;      ///< which event function changed sign (0 <= index < Plant::num_events())
};

/// Counters of the integrator.
struct SimulationStats {
  long steps = 0;             ///< CVODE steps (fixed-step mode: steps of dt)
  long rhs_evaluations = 0;   ///< right-hand side calls of the integrator's steps and Newton iterations
  /// Right-hand side calls CVODE made to build Newton matrices by difference quotients (one per
  /// state and matrix; not in rhs_evaluations); 0 where the plant and laws give an analytic
  /// Jacobian (stiff runs with dynamic laws on plants that provide Plant::jacobian) and in
  /// fixed-step mode.
  long jacobian_rhs_evaluations = 0;
  long restarts = 0;          ///< CVODE re-initialisations (mode switches and input corners)
  const char* solver = "";    ///< the solver mode actually used ("hybrid", "stiff", "fixed-step")
};

/// The sampled signals of one contact. All columns have the trajectory's rows() entries.
struct ContactColumns {
  std::vector<double> position;   ///< m or rad
  std::vector<double> velocity;   ///< m/s or rad/s
  std::vector<double> friction;   ///< friction force (N or N m), sign of motion
  std::vector<double> applied;    ///< net non-friction force on the body (N or N m)
  std::vector<double> current;    ///< motor current (A); 0 without a motor
  std::vector<double> voltage;    ///< motor voltage (V); 0 without a motor
  std::vector<double> reference;  ///< input signal (reference of a loop, command, base position)
  std::vector<double> stuck;      ///< 1 while stuck (hybrid mode), else 0
  /// Force the drive or controller commands on the contact (N or N m; PlantSignals::drive): what
  /// validation compares with a recorded force. Not part of a 1-DOF plant's CSV.
  std::vector<double> drive;
  /// Dynamic laws: law_state[i] is the column of internal state i (m or rad: bristle or element
  /// deflections); empty for static laws. Not part of the CSV.
  std::vector<std::vector<double>> law_state;
  /// Contacts with an environment (SimulationOptions::environments): the load F_load (N or N m)
  /// and the temperature (degC or K; the law's T_ref when none is given) at each row; empty
  /// otherwise. Part of a 1-DOF plant's CSV (after stuck) when not empty.
  std::vector<double> load, temperature;
};

/// Sampled simulation result. Its own ContactColumns are contact 0's (a 1-DOF plant's only
/// contact); `others` holds contacts 1..N-1. All columns have rows() entries. A plain value:
/// its columns are its own and are freed with it.
struct Trajectory : ContactColumns {
  std::vector<double> time;  ///< s
  /// Contact names (Contact::name), one per contact: {""} for a 1-DOF plant.
  std::vector<std::string> contact_names;
  std::vector<ContactColumns> others;  ///< contacts 1..N-1
  std::vector<ModeSwitch> switches;    ///< hybrid mode: every mode switch, in time order
  std::vector<PlantEvent> plant_events;  ///< every event of the plant's own event functions, in time order
  /// A backlash axis (open or in a loop): its motor's position (m or rad) at each row, the other
  /// body than the contact when the friction acts on the load; empty for other plants. Part of
  /// the CSV (after stuck, load and temperature) when not empty.
  std::vector<double> motor_position;
  SimulationStats stats;

  std::size_t rows() const { return time.size(); }
  /// Number of contacts (1 for a 1-DOF plant, and for an empty trajectory).
  int num_contacts() const { return 1 + static_cast<int>(others.size()); }
  /// Columns of contact i (0 <= i < num_contacts()). \throws std::out_of_range otherwise.
  const ContactColumns& contact(int i) const;
  /// A 1-DOF trajectory's column names in CSV order: time, position, velocity, friction, applied,
  /// current, voltage, reference, stuck (names() adds load, temperature for a contact with an
  /// environment, and motor_position for a backlash axis).
  static const std::vector<std::string>& column_names();
  /// This trajectory's column names in CSV order: column_names() when its plant has one unnamed
  /// contact; otherwise time, then for each contact NAME.position, NAME.velocity, NAME.friction,
  /// NAME.applied, NAME.current, NAME.voltage, NAME.reference, NAME.stuck, NAME.drive.
  std::vector<std::string> names() const;
  /// Column by name (one of names(); "drive" too for a 1-DOF trajectory).
  /// \throws std::invalid_argument listing the names.
  const std::vector<double>& column(std::string_view name) const;
  /// The CSV text: header row names(), then one row per sample (shortest round-trip form of each
  /// number, so reading it back gives the same doubles).
  std::string to_csv() const;
};

/// Name of a switch kind ("breakaway", "stick", "reversal", "impact").
const char* switch_kind_name(SwitchKind kind);

}  // namespace frictionlab
