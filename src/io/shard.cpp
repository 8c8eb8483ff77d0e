#include "frictionlab/io/shard.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "frictionlab/io/atomic_write.hpp"

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
  return std::get<std::string>(c);
}

Cell json_cell(const nlohmann::ordered_json& j, const std::string& where) {
  if (j.is_null()) return std::nan("");
  if (j.is_number()) return j.get<double>();
  if (j.is_string()) return j.get<std::string>();
  throw std::invalid_argument(where + ": a cell must be a number, a text or null");
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
                      {"rows_at", part.rows_at},
                      {"envelope", nlohmann::ordered_json::parse(part.envelope)},
                      {"rows", std::move(rows)}};
  return j.dump() + "\n";
}

Part read_part(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw std::invalid_argument(path + " is a directory; expected a part file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(path + ": cannot open the part file");
  std::stringstream ss;
  ss << in.rdbuf();
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(ss.str());
  } catch (const nlohmann::ordered_json::parse_error& e) {
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
  p.envelope = field("envelope", j.contains("envelope") && j["envelope"].is_object()).dump();
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
  return p;
}

Part merge_parts(const std::vector<Part>& parts, const std::vector<std::string>& names) {
  if (parts.empty()) throw std::invalid_argument("merge: no parts given");
  if (names.size() != parts.size()) throw std::invalid_argument("merge: one name per part is needed");
  const Part& first = parts.front();
  const std::string& first_name = names.front();
  std::vector<std::string> seen(first.shard.count);  // part name of each shard, by K-1
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
    if (p.table.columns != first.table.columns) foreign("columns");
    if (p.envelope != first.envelope || p.rows_at != first.rows_at) foreign("header (envelope)");
    std::string& slot = seen[p.shard.index - 1];
    if (!slot.empty())
      throw std::invalid_argument(names[i] + ": duplicated part: shard " + p.shard.text() + " is also " + slot);
    slot = names[i];
    const std::vector<std::size_t> want = shard_jobs(p.total, p.shard);
    if (p.table.index != want)
      throw std::invalid_argument(names[i] + ": shard " + p.shard.text() + " holds " + std::to_string(p.table.rows.size()) +
                                  " rows, not its " + std::to_string(want.size()) +
                                  " jobs in order (a truncated or edited part)");
  }
  for (std::size_t k = 0; k < seen.size(); ++k)
    if (seen[k].empty())
      throw std::invalid_argument("merge: missing part: shard " + std::to_string(k + 1) + "/" +
                                  std::to_string(seen.size()) + " was not given");
  Part out = first;
  out.shard = ShardSpec{};
  out.table.index.clear();
  out.table.rows.clear();
  std::vector<std::pair<std::size_t, const std::vector<Cell>*>> all;
  for (const Part& p : parts)
    for (std::size_t r = 0; r < p.table.rows.size(); ++r) all.emplace_back(p.table.index[r], &p.table.rows[r]);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [i, row] : all) {
    out.table.index.push_back(i);
    out.table.rows.push_back(*row);
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
  bool there = false;
  nlohmann::ordered_json::json_pointer at;
  try {
    at = nlohmann::ordered_json::json_pointer(part.rows_at);
    there = env.contains(at);
  } catch (const nlohmann::ordered_json::exception&) {
  }
  if (!there)
    throw std::invalid_argument("table_json: rows_at '" + part.rows_at +
                                "' is not a place in the envelope (it must hold an empty array there)");
  env[at] = std::move(rows);
  return env.dump(indent) + "\n";
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
