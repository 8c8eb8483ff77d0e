#pragma once
// An IDIM record (frictionlab/identify/idim.hpp) taken from a loaded data file by signal names.

#include <string>

#include "frictionlab/identify/idim.hpp"
#include "frictionlab/io/dataset.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Where the signals of an IDIM record are in a data file. The EMPS benchmark files use
/// {"t", "qm", "vir", "gtau"}.
struct IdimRecordNames {
  std::string time = "time";          ///< time column, s
  std::string position = "position";  ///< position column, m or rad
  std::string input = "input";        ///< drive command column; force = gain * input
  std::string gain = "1";             ///< a number, or the name of a scalar in the file (N or N m per unit input)
};

/// The IdimData of a dataset: time, position and force = gain * input, with the file's name and
/// SHA-256. \throws std::invalid_argument naming a missing column or scalar and listing what
/// the file has.
IdimData idim_record(const Dataset& data, const IdimRecordNames& names = {});

/// The same, moving the columns out of a data set that is no longer needed (no copies of
/// long records). Same throws; `data` is left with those columns empty.
IdimData idim_record(Dataset&& data, const IdimRecordNames& names = {});

}  // namespace frictionlab
