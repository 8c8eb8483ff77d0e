#include "frictionlab/identify/idim_record.hpp"

#include "frictionlab/io/columns.hpp"

#include <string>
#include <utility>

namespace frictionlab {

IdimData idim_record(const Dataset& data, const IdimRecordNames& names) {
  IdimData x;
  x.time = select_column(data, names.time, "time");
  x.position = select_column(data, names.position, "position");
  x.force = resolve_constant(data, names.gain, "gain") * select_column(data, names.input, "input");
  x.file = data.file;
  x.sha256 = data.sha256;
  return x;
}

IdimData idim_record(Dataset&& data, const IdimRecordNames& names) {
  // Every name is checked, in the copying form's order, before anything is moved.
  select_column(data, names.time, "time");
  select_column(data, names.position, "position");
  const double gain = resolve_constant(data, names.gain, "gain");
  select_column(data, names.input, "input");
  if (names.time == names.position || names.time == names.input || names.position == names.input) {
    return idim_record(static_cast<const Dataset&>(data), names);  // a column used twice: copy
  }
  IdimData x;
  x.time = std::move(data.column(names.time));
  x.position = std::move(data.column(names.position));
  x.force = std::move(data.column(names.input));
  x.force *= gain;
  x.file = data.file;
  x.sha256 = data.sha256;
  return x;
}

}  // namespace frictionlab
