#include "frictionlab/scenario/scenario_grid.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>


#include "frictionlab/format.hpp"

namespace frictionlab {
namespace {

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  for (std::size_t at = 0;;) {
    const auto dot = key.find('.', at);
    parts.push_back(key.substr(at, dot - at));
    if (dot == std::string::npos) break;
    at = dot + 1;
  }
  return parts;
}

bool is_index(const std::string& s) {
  return !s.empty() && s.size() < 9 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string keys_of(const YAML::Node& map) {
  std::string s;
  for (const auto& kv : map) s += (s.empty() ? "" : ", ") + kv.first.Scalar();
  return s.empty() ? "nothing" : s;
}

// Sets key (split) in `root` to `value`; returns whether the leaf was there before.
// \throws std::invalid_argument naming the first part that is missing or of the wrong kind.
bool set_key(YAML::Node root, const std::string& key, const std::string& value) {
  const std::vector<std::string> parts = split_key(key);
  YAML::Node node = root;
  std::string path;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    if (part.empty()) throw std::invalid_argument("--vary " + key + ": empty part in the key (two dots, or a dot at an end)");
    const bool leaf = i + 1 == parts.size();
    const std::string here = path.empty() ? std::string("the file's top level") : path;
    YAML::Node next;
    if (node.IsSequence()) {
      if (!is_index(part) || std::stoul(part) >= node.size())
        throw std::invalid_argument("--vary " + key + ": " + here + " is a list of " + std::to_string(node.size()) +
                                    " entries; '" + part + "' is not an index 0.." + std::to_string(node.size() - 1));
      next = node[std::stoul(part)];
    } else if (node.IsMap()) {
      next = node[part];
      if (!next.IsDefined() || next.IsNull()) {
        if (!leaf)
          throw std::invalid_argument("--vary " + key + ": the scenario has no '" + part + "' under " + here + " (it has " +
                                      keys_of(node) + ")");
        node[part] = value;
        return false;
      }
    } else {
      throw std::invalid_argument("--vary " + key + ": " + here + " is a value, not a section with '" + part + "' in it");
    }
    if (leaf) {
      if (!next.IsScalar())
        throw std::invalid_argument("--vary " + key + ": names a " + std::string(next.IsMap() ? "section" : "list") +
                                    ", not a number (it has " + (next.IsMap() ? keys_of(next) : std::string("entries")) +
                                    ")");
      double x = 0;
      const std::string& s = next.Scalar();
      const auto r = std::from_chars(s.data(), s.data() + s.size(), x);
      if (r.ec != std::errc() || r.ptr != s.data() + s.size())
        throw std::invalid_argument("--vary " + key + ": the scenario gives '" + s + "' there, not a number");
      next = value;
      return true;
    }
    node.reset(next);
    path += (path.empty() ? "" : ".") + part;
  }
  return true;
}

}  // namespace

struct ScenarioGrid::Impl {
  std::string path;
  std::vector<std::string> keys;
  ScenarioOptions options;
  YAML::Node root;
};

ScenarioGrid::ScenarioGrid(const std::string& path, std::vector<std::string> keys, const ScenarioOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->keys = std::move(keys);
  impl_->options = options;
  // The file as load_scenario reads it (and refuses it), once.
  (void)load_scenario(path, options);
  std::ifstream file(path);
  impl_->root = YAML::Load(file);
  if (impl_->options.base_dir.empty()) impl_->options.base_dir = std::filesystem::path(path).parent_path().string();
  // Each key alone, at the file's own value (or 1 when the file leaves it out).
  for (const std::string& key : impl_->keys) {
    YAML::Node probe = YAML::Clone(impl_->root);
    const bool present = set_key(probe, key, "1");
    if (present) continue;  // a number the file gives: the reader knows the field
    try {
      (void)scenario_from_yaml(probe, path, impl_->options);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--vary " + key + ": the scenario does not give it, and as a new field: " + e.what());
    }
  }
}

ScenarioGrid::~ScenarioGrid() = default;
ScenarioGrid::ScenarioGrid(ScenarioGrid&&) noexcept = default;
ScenarioGrid& ScenarioGrid::operator=(ScenarioGrid&&) noexcept = default;

Scenario ScenarioGrid::at(const std::vector<double>& values) const {
  if (values.size() != impl_->keys.size())
    throw std::invalid_argument("ScenarioGrid::at: " + std::to_string(values.size()) + " values for " +
                                std::to_string(impl_->keys.size()) + " keys");
  YAML::Node copy = YAML::Clone(impl_->root);
  std::string where = impl_->path + " with";
  for (std::size_t i = 0; i < values.size(); ++i) {
    set_key(copy, impl_->keys[i], format_exact(values[i]));
    where += (i ? ", " : " ") + impl_->keys[i] + "=" + format_exact(values[i]);
  }
  return scenario_from_yaml(copy, where, impl_->options);
}

const std::string& ScenarioGrid::path() const { return impl_->path; }
const std::vector<std::string>& ScenarioGrid::keys() const { return impl_->keys; }

}  // namespace frictionlab
