#include "fleet/shard.hpp"
#include "io/input_file.hpp"
#include "frictionlab/budget.hpp"
#include "frictionlab/io/json_text.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/atomic_write.hpp"

#include "frictionlab/format.hpp"

namespace frictionlab {
namespace {

constexpr int kPartVersion = 1;

bool parse_count(const std::string& s, std::size_t& out) {
  if (s.empty() || s.size() > 18 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  out = std::stoull(s);
  return out >= 1;
}

nlohmann::ordered_json cell_json(const Cell& c) {
  if (const double* x = std::get_if<double>(&c)) return std::isfinite(*x) ? nlohmann::ordered_json(*x) : nlohmann::ordered_json(nullptr);
  if (const std::int64_t* i = std::get_if<std::int64_t>(&c)) return *i;
  if (const bool* b = std::get_if<bool>(&c)) return *b;
  return std::get<std::string>(c);
}

// The inverse of cell_json: JSON keeps "1.0" (a double) apart from "1" (an integer).
Cell json_cell(const nlohmann::ordered_json& j, const std::string& where) {
  if (j.is_null()) return std::nan("");
  if (j.is_boolean()) return j.get<bool>();
  if (j.is_number_integer()) return j.get<std::int64_t>();
  if (j.is_number()) return j.get<double>();
  if (j.is_string()) return j.get<std::string>();
  throw std::invalid_argument(where + ": a cell must be a number, a text, true/false or null");
}

// The JSON pointer `text` (the part's field `field`) to a place that `env` has.
nlohmann::ordered_json::json_pointer place_in(const nlohmann::ordered_json& env, const std::string& field,
                                              const std::string& text, const std::string& hint) {
  try {
    nlohmann::ordered_json::json_pointer at(text);
    if (env.contains(at)) return at;
  } catch (const nlohmann::ordered_json::exception&) {
  }
  throw std::invalid_argument("table_json: " + field + " '" + text + "' is not a place in the envelope" + hint);
}

// The columns that do not come from the rows: all but the grown ones.
std::vector<std::string> fixed_columns(const RowTable& t) {
  if (!t.grown) return t.columns;
  std::vector<std::string> out(t.columns.begin(), t.columns.begin() + static_cast<std::ptrdiff_t>(t.grown->begin));
  out.insert(out.end(), t.columns.begin() + static_cast<std::ptrdiff_t>(t.grown->end), t.columns.end());
  return out;
}

std::string number_text(double x) {
  if (!std::isfinite(x)) return "";
  return format_exact(x);  // the shortest form that reads back exactly
}

std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string ShardSpec::text() const { return std::to_string(index) + "/" + std::to_string(count); }

ShardSpec parse_shard(const std::string& text, const std::string& option) {
  const std::string head = option + " '" + text + "': ";
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw std::invalid_argument(head + "expected K/N (shard K of N, e.g. 2/8)");
  ShardSpec s;
  if (!parse_count(text.substr(0, slash), s.index))
    throw std::invalid_argument(head + "K must be a positive integer (shard K of N, 1-based)");
  if (!parse_count(text.substr(slash + 1), s.count)) throw std::invalid_argument(head + "N must be a positive integer");
  if (s.index > s.count)
    throw std::invalid_argument(head + "K = " + std::to_string(s.index) + " must be <= N = " + std::to_string(s.count));
  return s;
}

bool in_shard(std::size_t i, const ShardSpec& shard) { return i % shard.count == shard.index - 1; }

std::vector<std::size_t> shard_jobs(std::size_t total, const ShardSpec& shard) {
  std::vector<std::size_t> jobs;
  for (std::size_t i = shard.index - 1; i < total; i += shard.count) jobs.push_back(i);
  return jobs;
}

std::string part_to_json(const Part& part) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (std::size_t r = 0; r < part.table.rows.size(); ++r) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array({part.table.index.at(r)});
    for (const Cell& c : part.table.rows[r]) row.push_back(cell_json(c));
    rows.push_back(std::move(row));
  }
  nlohmann::ordered_json j = {{"frictionlab_part", kPartVersion},
                      {"command", part.command},
                      {"key", part.key},
                      {"shard", part.shard.text()},
                      {"total", part.total},
                      {"columns", part.table.columns},
                      {"rows_at", part.rows_at}};
  if (!part.columns_at.empty()) j["columns_at"] = part.columns_at;
  if (const auto& g = part.table.grown) j["grown"] = {{"begin", g->begin}, {"end", g->end}, {"first", g->first}};
  j["envelope"] = nlohmann::ordered_json::parse(part.envelope);
  j["rows"] = std::move(rows);
  return json_text(j) + "\n";
}

Part read_part(const std::string& path) {
  const std::string text = read_input_file(path, "part file", errc::input_invalid);
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::ordered_json::exception& e) {
    // parse_error, and out_of_range for a number beyond a double (1e400): both are not JSON we read.
    throw std::invalid_argument(path + ": not a part file (not JSON: " + e.what() + ")");
  }
  const std::string head = path + ": not a frictionlab part file";
  if (!j.is_object() || !j.contains("frictionlab_part"))
    throw std::invalid_argument(head + " (no \"frictionlab_part\" field; parts are what a --shard run writes)");
  if (j["frictionlab_part"] != kPartVersion)
    throw std::invalid_argument(path + ": part format " + j["frictionlab_part"].dump() + " is not " +
                                std::to_string(kPartVersion) + " (written by another frictionlab version)");
  const auto field = [&](const char* name, bool ok) -> const nlohmann::ordered_json& {
    if (!j.contains(name) || !ok) throw std::invalid_argument(head + " (field \"" + name + "\" missing or malformed)");
    return j[name];
  };
  Part p;
  p.command = field("command", j.contains("command") && j["command"].is_string()).get<std::string>();
  p.key = field("key", j.contains("key") && j["key"].is_string()).get<std::string>();
  try {
    p.shard = parse_shard(field("shard", j.contains("shard") && j["shard"].is_string()).get<std::string>(),
                          path + ": shard");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(e.what());
  }
  p.total = field("total", j.contains("total") && j["total"].is_number_unsigned()).get<std::size_t>();
  const nlohmann::ordered_json& cols = field("columns", j.contains("columns") && j["columns"].is_array());
  for (const auto& c : cols) {
    if (!c.is_string()) throw std::invalid_argument(head + " (a column name is not a text)");
    p.table.columns.push_back(c.get<std::string>());
  }
  p.rows_at = field("rows_at", j.contains("rows_at") && j["rows_at"].is_string()).get<std::string>();
  if (j.contains("columns_at"))
    p.columns_at = field("columns_at", j["columns_at"].is_string()).get<std::string>();
  if (j.contains("grown")) {
    const auto& g = j["grown"];
    const auto count = [&](const char* name) {
      return g.is_object() && g.contains(name) && g[name].is_number_unsigned();
    };
    const bool ok = count("begin") && count("end") && g.contains("first") && g["first"].is_array() &&
                    g["begin"].get<std::size_t>() <= g["end"].get<std::size_t>() &&
                    g["end"].get<std::size_t>() <= p.table.columns.size() &&
                    g["first"].size() == g["end"].get<std::size_t>() - g["begin"].get<std::size_t>() &&
                    std::all_of(g["first"].begin(), g["first"].end(), [](const auto& f) { return f.is_number_unsigned(); });
    field("grown", ok);
    p.table.grown = GrownColumns{g["begin"].get<std::size_t>(), g["end"].get<std::size_t>(),
                                 g["first"].get<std::vector<std::size_t>>()};
  }
  p.envelope = json_text(field("envelope", j.contains("envelope") && j["envelope"].is_object()));
  const nlohmann::ordered_json& rows = field("rows", j.contains("rows") && j["rows"].is_array());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::string where = path + ": row " + std::to_string(r + 1);
    const auto& row = rows[r];
    if (!row.is_array() || row.size() != p.table.columns.size() + 1 || !row[0].is_number_unsigned())
      throw std::invalid_argument(where + ": expected [index, " + std::to_string(p.table.columns.size()) + " cells]");
    p.table.index.push_back(row[0].get<std::size_t>());
    std::vector<Cell> cells;
    for (std::size_t c = 1; c < row.size(); ++c) cells.push_back(json_cell(row[c], where));
    p.table.rows.push_back(std::move(cells));
  }
  // The total and the shard count size what merge allocates: a part's own rows bound them, so an
  // edited total (1e18) is refused here, not allocated.
  check_work(static_cast<double>(p.shard.count), "shards", path + ": shard " + p.shard.text(), {.file = path, .key = "shard"});
  const std::size_t jobs = p.total >= p.shard.index ? (p.total - p.shard.index) / p.shard.count + 1 : 0;
  if (jobs != p.table.rows.size())
    throw InputError(errc::input_invalid,
                     path + ": \"total\": " + std::to_string(p.total) + " jobs give shard " + p.shard.text() + " " +
                         std::to_string(jobs) + " rows, but the part holds " + std::to_string(p.table.rows.size()) +
                         " (a truncated or edited part)",
                     {.file = path, .key = "total", .value = std::to_string(p.total)});
  return p;
}

Part merge_parts(const std::vector<Part>& parts, const std::vector<std::string>& names) {
  if (parts.empty()) throw std::invalid_argument("merge: no parts given");
  if (names.size() != parts.size()) throw std::invalid_argument("merge: one name per part is needed");
  const Part& first = parts.front();
  const std::string& first_name = names.front();
  // Part name of each shard given, by K. A map, not a vector of the shard count: a part that says
  // "1/999999999" must be refused as incomplete, not allocate a slot for every shard.
  std::map<std::size_t, std::string> seen;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Part& p = parts[i];
    const auto foreign = [&](const std::string& what) {
      throw std::invalid_argument(names[i] + ": foreign part: its " + what + " differs from " + first_name +
                                  "'s (parts of another run: another scenario, grid or option)");
    };
    if (p.command != first.command) foreign("command (" + p.command + " against " + first.command + ")");
    if (p.key != first.key) foreign("key");
    if (p.shard.count != first.shard.count)
      foreign("shard count (" + p.shard.text() + " against " + first.shard.text() + ")");
    if (p.total != first.total) foreign("total");
    if (fixed_columns(p.table) != fixed_columns(first.table) || p.table.grown.has_value() != first.table.grown.has_value() ||
        (p.table.grown && p.table.grown->begin != first.table.grown->begin))
      foreign("columns");
    if (p.envelope != first.envelope || p.rows_at != first.rows_at || p.columns_at != first.columns_at)
      foreign("header (envelope)");
    std::string& slot = seen[p.shard.index];
    if (!slot.empty())
      throw std::invalid_argument(names[i] + ": duplicated part: shard " + p.shard.text() + " is also " + slot);
    slot = names[i];
    const std::vector<std::size_t> want = shard_jobs(p.total, p.shard);
    if (p.table.index != want)
      throw std::invalid_argument(names[i] + ": shard " + p.shard.text() + " holds " + std::to_string(p.table.rows.size()) +
                                  " rows, not its " + std::to_string(want.size()) +
                                  " jobs in order (a truncated or edited part)");
  }
  // Shards are 1..count and each was given once: the first K not among them is missing (at most
  // parts.size() + 1 steps).
  for (std::size_t k = 1; k <= first.shard.count; ++k)
    if (!seen.count(k))
      throw std::invalid_argument("merge: missing part: shard " + std::to_string(k) + "/" +
                                  std::to_string(first.shard.count) + " was not given");
  Part out = first;
  out.shard = ShardSpec{};
  out.table.index.clear();
  out.table.rows.clear();
  // Each part's columns in the merged table: the grown columns in order of first appearance by
  // job index, as the unsharded run lays them out (two first seen in one row come from one part,
  // in that row's order).
  std::vector<std::vector<std::size_t>> place(parts.size());
  if (first.table.grown) {
    struct Seen {
      std::size_t first, part, column;
    };
    std::map<std::string, Seen> seen_columns;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const GrownColumns& g = *parts[i].table.grown;
      for (std::size_t c = g.begin; c < g.end; ++c) {
        const Seen s{g.first[c - g.begin], i, c};
        auto [it, added] = seen_columns.emplace(parts[i].table.columns[c], s);
        if (!added && std::tie(s.first, s.column) < std::tie(it->second.first, it->second.column)) it->second = s;
      }
    }
    std::vector<std::pair<std::string, Seen>> order(seen_columns.begin(), seen_columns.end());
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
      return std::tie(a.second.first, a.second.column) < std::tie(b.second.first, b.second.column);
    });
    const GrownColumns& g0 = *first.table.grown;
    std::vector<std::string> columns(first.table.columns.begin(), first.table.columns.begin() + g0.begin);
    GrownColumns grown{g0.begin, g0.begin + order.size(), {}};
    for (const auto& [name, s] : order) {
      columns.push_back(name);
      grown.first.push_back(s.first);
    }
    columns.insert(columns.end(), first.table.columns.begin() + g0.end, first.table.columns.end());
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const RowTable& t = parts[i].table;
      for (std::size_t c = 0; c < t.columns.size(); ++c) {
        const GrownColumns& g = *t.grown;
        if (c < g.begin)
          place[i].push_back(c);
        else if (c >= g.end)
          place[i].push_back(c - g.end + grown.end);
        else
          place[i].push_back(static_cast<std::size_t>(
              std::find(columns.begin() + grown.begin, columns.begin() + grown.end, t.columns[c]) - columns.begin()));
      }
    }
    out.table.columns = std::move(columns);
    out.table.grown = std::move(grown);
  } else {
    for (std::size_t i = 0; i < parts.size(); ++i)
      for (std::size_t c = 0; c < first.table.columns.size(); ++c) place[i].push_back(c);
  }
  std::vector<std::tuple<std::size_t, std::size_t, const std::vector<Cell>*>> all;  // job, part, row
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (std::size_t r = 0; r < parts[i].table.rows.size(); ++r)
      all.emplace_back(parts[i].table.index[r], i, &parts[i].table.rows[r]);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
  for (const auto& [job, i, row] : all) {
    std::vector<Cell> cells(out.table.columns.size(), Cell{std::nan("")});
    for (std::size_t c = 0; c < row->size(); ++c) cells[place[i][c]] = (*row)[c];
    out.table.index.push_back(job);
    out.table.rows.push_back(std::move(cells));
  }
  return out;
}

std::string table_csv(const RowTable& table) {
  std::string out;
  for (std::size_t c = 0; c < table.columns.size(); ++c) out += (c ? "," : "") + csv_text(table.columns[c]);
  out += "\n";
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) out += ",";
      if (const double* x = std::get_if<double>(&row[c]))
        out += number_text(*x);
      else if (const std::int64_t* i = std::get_if<std::int64_t>(&row[c]))
        out += std::to_string(*i);
      else if (const bool* b = std::get_if<bool>(&row[c]))
        out += *b ? "true" : "false";
      else
        out += csv_text(std::get<std::string>(row[c]));
    }
    out += "\n";
  }
  return out;
}

std::string table_json(const Part& part, int indent) {
  nlohmann::ordered_json env;
  try {
    env = nlohmann::ordered_json::parse(part.envelope);
  } catch (const nlohmann::ordered_json::parse_error& e) {
    throw std::invalid_argument(std::string("table_json: the envelope is not JSON: ") + e.what());
  }
  if (!env.is_object()) throw std::invalid_argument("table_json: the envelope is not a JSON object");
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const auto& row : part.table.rows) {
    nlohmann::ordered_json o = nlohmann::ordered_json::object();
    for (std::size_t c = 0; c < row.size(); ++c) o[part.table.columns.at(c)] = cell_json(row[c]);
    rows.push_back(std::move(o));
  }
  env[place_in(env, "rows_at", part.rows_at, " (it must hold an empty array there)")] = std::move(rows);
  if (!part.columns_at.empty()) env[place_in(env, "columns_at", part.columns_at, "")] = part.table.columns;
  return json_text(env, indent) + "\n";
}

std::size_t grow_column(RowTable& table, const std::string& name, std::size_t job) {
  if (!table.grown) throw std::logic_error("grow_column: the table has no grown columns");
  GrownColumns& g = *table.grown;
  const auto begin = table.columns.begin() + static_cast<std::ptrdiff_t>(g.begin);
  const auto end = table.columns.begin() + static_cast<std::ptrdiff_t>(g.end);
  if (const auto it = std::find(begin, end, name); it != end) return static_cast<std::size_t>(it - table.columns.begin());
  const std::size_t at = g.end;
  table.columns.insert(end, name);
  for (auto& row : table.rows) row.insert(row.begin() + static_cast<std::ptrdiff_t>(at), Cell{std::nan("")});
  g.first.push_back(job);
  ++g.end;
  return at;
}

void write_table(const std::string& path, const Part& part, bool overwrite) {
  const std::string ext = std::filesystem::path(path).extension().string();
  std::string text;
  if (ext == ".csv")
    text = table_csv(part.table);
  else if (ext == ".json")
    text = table_json(part);
  else
    throw std::invalid_argument(path + ": unknown output type '" + ext + "'; expected a .csv or .json file");
  AtomicWriteOptions w;
  w.overwrite = overwrite;
  write_file_atomic(path, text, w);
}

}  // namespace frictionlab
