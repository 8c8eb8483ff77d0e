#pragma once
// The interpolation points of a Table (models/table.hpp), shared by the table itself and the code
// generator of export/c_export.cpp, which writes them into a C header: one definition of how a table
// splits into its two directions and of its monotone slopes, so the header interpolates exactly
// as the library does.

#include <vector>

namespace frictionlab::detail {

/// One direction of a table: |v| ascending (m/s or rad/s) and |F| (N or N m), one per point.
struct TableSide {
  std::vector<double> speed, level;
};

/// The positive and negative directions of a valid table (velocity, force as Table takes them):
/// each direction's points by |v| ascending; a table with one direction only is mirrored.
void table_sides(const std::vector<double>& velocity, const std::vector<double>& force, TableSide& pos, TableSide& neg);

/// Fritsch-Carlson monotone Hermite slopes d|F|/d|v| (N s/m or N m s/rad) at each point of a side
/// (at least 2 points).
std::vector<double> monotone_slopes(const std::vector<double>& v, const std::vector<double>& f);

}  // namespace frictionlab::detail
