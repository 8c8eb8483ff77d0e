#include "frictionlab/analysis/drift.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <regex>
#include <stdexcept>

namespace frictionlab {
namespace {

constexpr double kSecondsPerDay = 86400.0;

// A calendar date and time of day, checked; the calendar arithmetic is std::chrono's (C++20).
std::optional<LogDate> make_date(int y, int mo, int d, int h, int mi, int s, bool has_time) {
  using namespace std::chrono;
  const year_month_day ymd{year{y}, month{static_cast<unsigned>(mo)}, day{static_cast<unsigned>(d)}};
  if (!ymd.ok() || y < 1970 || y > 2999 || h < 0 || h > 23 || mi < 0 || mi > 59 || s < 0 || s > 59) return std::nullopt;
  const double days = static_cast<double>(sys_days{ymd}.time_since_epoch().count());
  LogDate out;
  out.posix_seconds = days * kSecondsPerDay + h * 3600.0 + mi * 60.0 + s;
  char buf[64];  // room for any int, as the compiler's format check assumes
  if (has_time)
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d", y, mo, d, h, mi, s);
  else
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02d", y, mo, d);
  out.iso = buf;
  return out;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::optional<LogDate> log_date_from_name(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  // Date, then an optional time after one separator. Tried at every start of a digit run; the
  // match must end where the digits do, so that "120261102" is not read as a date.
  static const std::regex form(
      R"((\d{4})([-_]?)(\d{2})\2(\d{2})(?:[T_\- ](\d{2})[:\-]?(\d{2})(?:[:\-]?(\d{2}))?)?)");
  std::optional<LogDate> last;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (!is_digit(name[i]) || (i > 0 && is_digit(name[i - 1]))) continue;
    std::smatch m;
    const std::string rest = name.substr(i);
    if (!std::regex_search(rest, m, form, std::regex_constants::match_continuous)) continue;
    const auto end = static_cast<std::size_t>(m.length(0));
    if (end < rest.size() && is_digit(rest[end])) {
      // A time part that runs into more digits: try the date alone.
      const auto date_end = static_cast<std::size_t>(m.position(4) + m.length(4));
      if (date_end < rest.size() && is_digit(rest[date_end])) continue;
      if (auto d = make_date(std::stoi(m[1]), std::stoi(m[3]), std::stoi(m[4]), 0, 0, 0, false)) last = d;
      continue;
    }
    const int y = std::stoi(m[1]), mo = std::stoi(m[3]), day = std::stoi(m[4]);
    auto d = m[5].matched ? make_date(y, mo, day, std::stoi(m[5]), std::stoi(m[6]), m[7].matched ? std::stoi(m[7]) : 0, true)
                          : std::nullopt;
    if (!d) d = make_date(y, mo, day, 0, 0, 0, false);  // no time, or digits that are no time of day: the day
    if (d) last = d;
  }
  return last;
}

LogDate log_date_from_posix(double seconds) {
  using namespace std::chrono;
  constexpr double kYear3000 = 32503680000.0;  // 3000-01-01T00:00:00 UTC
  if (!std::isfinite(seconds) || seconds < 0 || seconds >= kYear3000)
    throw std::invalid_argument("log date: POSIX time " + std::to_string(seconds) +
                                " s: expected seconds since 1970-01-01 UTC, from 1970 to 2999");
  const double days = std::floor(seconds / kSecondsPerDay);
  const year_month_day ymd{sys_days{std::chrono::days{static_cast<long>(days)}}};
  const auto of_day = static_cast<long>(std::floor(seconds - days * kSecondsPerDay));
  auto d = make_date(static_cast<int>(ymd.year()), static_cast<int>(static_cast<unsigned>(ymd.month())),
                     static_cast<int>(static_cast<unsigned>(ymd.day())), static_cast<int>(of_day / 3600),
                     static_cast<int>(of_day / 60 % 60), static_cast<int>(of_day % 60), true);
  d->posix_seconds = seconds;  // keep the fraction of a second
  return *d;
}

std::vector<DriftRow> drift_table(const std::vector<DriftSample>& samples, double threshold) {
  if (!std::isfinite(threshold) || threshold <= 0)
    throw std::invalid_argument("drift: threshold = " + std::to_string(threshold) +
                                ": expected a finite number > 0 (a multiple of the combined std)");
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const DriftSample& s = samples[i];
    if (!std::isfinite(s.value))
      throw std::invalid_argument("drift: " + s.file + ": parameter " + s.parameter + " = " + std::to_string(s.value) +
                                  " " + s.unit + ": expected a finite value");
    auto [it, added] = groups.try_emplace(s.parameter);
    if (added) order.push_back(s.parameter);
    it->second.push_back(i);
  }
  std::vector<DriftRow> rows;
  rows.reserve(samples.size());
  for (const auto& name : order) {
    auto& g = groups[name];
    std::stable_sort(g.begin(), g.end(), [&](std::size_t a, std::size_t b) {
      return samples[a].date.posix_seconds < samples[b].date.posix_seconds;
    });
    for (std::size_t k = 0; k < g.size(); ++k) {
      DriftRow r;
      r.sample = samples[g[k]];
      r.change = std::nan("");
      r.combined_std = std::nan("");
      if (k > 0) {
        const DriftSample& prev = samples[g[k - 1]];
        r.change = r.sample.value - prev.value;
        r.combined_std = std::hypot(r.sample.std, prev.std);  // NaN when either is unknown
        r.flagged = std::isfinite(r.combined_std) && std::fabs(r.change) > threshold * r.combined_std;
      }
      rows.push_back(std::move(r));
    }
  }
  return rows;
}

}  // namespace frictionlab
