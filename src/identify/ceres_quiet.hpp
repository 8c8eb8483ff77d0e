#pragma once
// Ceres reports through glog: a cost that turns non-finite prints a screenful of residuals and
// "WARNING: Logging before InitGoogleLogging() is written to STDERR" on stderr, which breaks the
// command line's one-line messages. The fits read Ceres' outcome from its Summary (a failure is a
// result with status error), so glog's lines below FATAL are not shown.

#include <glog/logging.h>

namespace frictionlab::detail {

inline void quiet_ceres_logging() { FLAGS_minloglevel = google::GLOG_FATAL; }

}  // namespace frictionlab::detail
