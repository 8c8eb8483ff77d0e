// The readers' messages name the library's parameters (drop_invalid, names, scale), or the name
// their caller gives (the command line's flags): never a command-line flag of their own.
#include <gtest/gtest.h>

#include <string>

#include "error_message.hpp"
#include "temp_dir.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/io/csv.hpp"

namespace fl = frictionlab;
using frictionlab::testing::error_of;
using frictionlab::testing::TempDir;

namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(ReaderMessages, NameTheParameterOrTheCallersName) {
  TempDir d;
  const std::string hole = d.file("hole.csv", "time,position\n0,0\n0.001,\n0.002,0.2\n");
  std::string msg = error_of([&] { fl::read_csv(hole); });
  EXPECT_TRUE(contains(msg, "(use drop_invalid to skip such rows)")) << msg;
  fl::CsvOptions cli;
  cli.drop_invalid_option = "--drop-invalid";
  msg = error_of([&] { fl::read_csv(hole, cli); });
  EXPECT_TRUE(contains(msg, "(use --drop-invalid to skip such rows)")) << msg;

  fl::CsvOptions detect;
  detect.header = fl::CsvHeader::detect;
  const fl::Dataset bare = fl::read_csv(d.file("bare.csv", "0,0\n0.001,0.1\n0.002,0.2\n"), detect);
  msg = error_of([&] { fl::select_column(bare, "time", "time"); });
  EXPECT_TRUE(contains(msg, "unless named with names)")) << msg;
  EXPECT_FALSE(contains(msg, "--")) << msg;

  fl::Dataset data = fl::read_csv(d.file("ok.csv", "time,position\n0,0\n0.001,0.1\n"));
  msg = error_of([&] { fl::apply_scales(data, {"position"}); });
  EXPECT_TRUE(contains(msg, "scale 'position': expected NAME=FACTOR")) << msg;
  EXPECT_FALSE(contains(msg, "--")) << msg;
  msg = error_of([&] { fl::apply_scales(data, {"velocity=2"}, "--scale"); });
  EXPECT_TRUE(contains(msg, "no column 'velocity' (--scale 'velocity=2')")) << msg;
}
