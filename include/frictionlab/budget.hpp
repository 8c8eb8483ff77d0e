#pragma once
// The work and memory budget: every command computes, before it starts, the memory its largest
// allocation needs (bytes) and the work it will do (work units: samples, solver steps, runs, grid
// points, bytes read), and refuses input that exceeds the budget with an InputError naming the key
// or option and the size (code budget.memory or budget.work, in the table of error.hpp; the CLI
// exits 2). The budget is counted in work, never in seconds, so the same input is accepted or
// refused on every machine with the same memory.
//
// Defaults: memory, half of what this process may use (the cgroup's memory.max when there is one,
// else the physical memory); work, 1e9 units per command (a simulation of 1e9 output rows or solver
// steps, 1e9 runs, ...). One factor raises both (`frictionlab --budget FACTOR`, C++
// set_budget_factor): the work budget is multiplied by it, the memory budget too but never
// beyond all the memory the process may use.
//
// The budget is one process-wide setting (an atomic), read by every check.

#include <string>

#include "frictionlab/error.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The default work budget (work units) of one command at factor 1.
inline constexpr double kDefaultWorkBudget = 1e9;

/// The work of one run's setup (a scenario made, a solver started, an output opened), in work
/// units, counted for each run of a batch (map points, Monte Carlo runs) besides its samples.
inline constexpr double kWorkPerRun = 1000;

/// Memory this process may use (bytes): the cgroup v2 `memory.max` (or v1 `memory.limit_in_bytes`)
/// of the process's cgroup when one is set and below the physical memory, else the physical memory
/// (1 GiB when neither can be read). Read once.
double memory_available();

/// Sets the budget factor (dimensionless, finite, >= 1e-6; default 1). Throws InputError
/// (option.out_of_range, option `--budget`) otherwise. Process-wide.
void set_budget_factor(double factor);

/// The budget factor in effect (default 1).
double budget_factor();

/// The memory budget (bytes): min(memory_available(), 0.5 * factor * memory_available()).
double memory_budget();

/// The work budget (work units): factor * kDefaultWorkBudget.
double work_budget();

/// Throws InputError(budget.memory, fields) when need_bytes (bytes; NaN and inf count as too large)
/// exceeds memory_budget(). The message reads "WHAT: that needs N of memory; the memory budget is
/// M (...)", with WHAT naming the key or option and its value, e.g. "s.yaml: duration: 1e9 s ...".
void check_memory(double need_bytes, const std::string& what, const ErrorFields& fields = {});

/// Throws InputError(budget.work, fields) when units (work units; NaN and inf count as too large)
/// exceeds work_budget(): "WHAT: that is N UNIT; the work budget is M work units (...)". unit
/// names what is counted ("output rows", "runs", "samples").
void check_work(double units, const std::string& unit, const std::string& what, const ErrorFields& fields = {});

/// A byte count for messages: "7.2 TB", "512 MB" (powers of 1000).
std::string format_bytes(double bytes);

}  // namespace frictionlab
