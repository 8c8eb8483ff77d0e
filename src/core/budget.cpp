// The work and memory budget (frictionlab/budget.hpp).
#include "frictionlab/budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace frictionlab {
namespace {

std::atomic<double> g_factor{1.0};

// A limit in bytes read from a cgroup file: a number, or "max" / a huge value for none.
double read_limit(const std::string& file) {
  std::ifstream in(file);
  std::string text;
  if (!(in >> text) || text == "max") return INFINITY;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return (end != text.c_str() && v > 0) ? v : INFINITY;
}

// The process's cgroup path (v2: the "0::" line of /proc/self/cgroup; v1: the memory controller's).
double cgroup_limit() {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  double limit = INFINITY;
  while (std::getline(in, line)) {
    const auto a = line.find(':'), b = line.find(':', a == std::string::npos ? 0 : a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    const std::string controllers = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
    if (controllers.empty()) {
      // v2: the limit of this cgroup and of each parent up to the root (the smallest holds).
      for (std::string p = path; !p.empty();) {
        limit = std::min(limit, read_limit("/sys/fs/cgroup" + (p == "/" ? std::string() : p) + "/memory.max"));
        if (p == "/") break;
        const auto slash = p.find_last_of('/');
        p = slash == 0 ? "/" : p.substr(0, slash);
      }
    } else if (("," + controllers + ",").find(",memory,") != std::string::npos) {
      limit = std::min(limit, read_limit("/sys/fs/cgroup/memory" + path + "/memory.limit_in_bytes"));
      limit = std::min(limit, read_limit("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
    }
  }
  return limit;
}

double compute_available() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  const double physical = (pages > 0 && page > 0) ? static_cast<double>(pages) * static_cast<double>(page) : 1073741824.0;
  return std::min(physical, cgroup_limit());
}

std::string format_units(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string budget_note() {
  const double f = budget_factor();
  return f == 1.0 ? std::string("the default") : "the default times --budget " + format_units(f);
}

}  // namespace

double memory_available() {
  static const double available = compute_available();
  return available;
}

void set_budget_factor(double factor) {
  if (!(std::isfinite(factor) && factor >= 1e-6)) {
    throw InputError(errc::option_out_of_range, "--budget = " + format_units(factor) + " must be a finite factor >= 1e-6",
                     {.option = "--budget", .value = format_units(factor)});
  }
  g_factor.store(factor);
}

double budget_factor() { return g_factor.load(); }

double memory_budget() {
  const double all = memory_available();
  return std::min(all, 0.5 * budget_factor() * all);
}

double work_budget() { return budget_factor() * kDefaultWorkBudget; }

void check_memory(double need_bytes, const std::string& what, const ErrorFields& fields) {
  const double limit = memory_budget();
  if (need_bytes <= limit) return;
  throw InputError(errc::budget_memory,
                   what + ": that needs " + (std::isfinite(need_bytes) ? format_bytes(need_bytes) + " of memory" : std::string("unbounded memory")) +
                       "; the memory budget is " + format_bytes(limit) + " (" + budget_note() + ": " +
                       (budget_factor() == 1.0 ? "half" : "a share") + " of the " + format_bytes(memory_available()) +
                       " this process may use; raise it with --budget FACTOR, in Python frictionlab.set_budget_factor(FACTOR))",
                   fields);
}

void check_work(double units, const std::string& unit, const std::string& what, const ErrorFields& fields) {
  const double limit = work_budget();
  if (units <= limit) return;
  throw InputError(errc::budget_work,
                   what + ": that is " + (std::isfinite(units) ? format_units(units) : std::string("unbounded")) + " " + unit +
                       "; the work budget is " + format_units(limit) + " work units (" + budget_note() +
                       "; raise it with --budget FACTOR, in Python frictionlab.set_budget_factor(FACTOR))",
                   fields);
}

std::string format_bytes(double bytes) {
  static const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  char buf[64];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return buf;
}

}  // namespace frictionlab
