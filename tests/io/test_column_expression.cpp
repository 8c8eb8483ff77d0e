// Derived columns (io/column_expression.hpp): values, precedence, quoting, and the messages of
// every way an expression can be wrong.
#include <gtest/gtest.h>

#include <string>

#include "error_message.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/io/column_expression.hpp"

namespace frictionlab {
namespace {

using testing::error_of;

// A torque-sensing joint's log: motor torque from current, the link torque sensor, and a column
// whose name holds a space and an operator.
Dataset joint_log() {
  Dataset d;
  d.file = "joint.csv";
  d.add_column("TorqueCur1", (Eigen::VectorXd(3) << 5.0, 6.0, 7.5).finished());
  d.add_column("Torque1", (Eigen::VectorXd(3) << 1.0, 2.5, 3.0).finished());
  d.add_column("Current [A]", (Eigen::VectorXd(3) << 1.0, 2.0, 4.0).finished());
  d.add_column("a-b", (Eigen::VectorXd(3) << 9.0, 9.0, 9.0).finished());
  d.scalars["kt"] = 0.5;
  d.lines = {2, 3, 5};
  return d;
}

TEST(ColumnExpression, DifferenceOfTwoColumns) {
  const Eigen::VectorXd f = finite_signal(joint_log(), "TorqueCur1 - Torque1", "--force");
  ASSERT_EQ(f.size(), 3);
  // Sums and differences of a few small binary fractions are exact in double.
  EXPECT_EQ(f[0], 4.0);
  EXPECT_EQ(f[1], 3.5);
  EXPECT_EQ(f[2], 4.5);
}

TEST(ColumnExpression, PrecedenceParenthesesUnaryMinusAndScalars) {
  const Dataset d = joint_log();
  // 2 + 3 * x binds as 2 + (3 x); -(a - b) / 2; kt is the file's scalar.
  const Eigen::VectorXd a = evaluate_column_expression(d, "2 + 3 * Torque1", "--force");
  const Eigen::VectorXd b = evaluate_column_expression(d, "-(TorqueCur1 - Torque1) / 2", "--force");
  const Eigen::VectorXd c = evaluate_column_expression(d, "kt * `Current [A]` - 1e-1", "--force");
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(a[k], 2 + 3 * d.column("Torque1")[k]);
    EXPECT_DOUBLE_EQ(b[k], -(d.column("TorqueCur1")[k] - d.column("Torque1")[k]) / 2);
    EXPECT_DOUBLE_EQ(c[k], 0.5 * d.column("Current [A]")[k] - 0.1);
  }
}

TEST(ColumnExpression, AColumnNamedLikeAnExpressionIsThatColumn) {
  const Dataset d = joint_log();
  EXPECT_FALSE(is_column_expression(d, "a-b"));
  EXPECT_EQ(finite_signal(d, "a-b")[0], 9.0);
  EXPECT_FALSE(is_column_expression(d, "Torque2"));  // a plain unknown name keeps "no column"
  EXPECT_TRUE(is_column_expression(d, "Torque2 * 2"));
}

TEST(ColumnExpression, MessagesNameTheOptionTheExpressionAndWhere) {
  const Dataset d = joint_log();
  EXPECT_EQ(error_of([&] { evaluate_column_expression(d, "TorqueCur1 - Torq1", "--force"); }),
            "joint.csv: no column 'Torq1' (--force 'TorqueCur1 - Torq1'); the file has columns: TorqueCur1, Torque1, "
            "Current [A], a-b (scalars: kt)");
  const std::string syntax = error_of([&] { evaluate_column_expression(d, "TorqueCur1 -", "--force"); });
  EXPECT_NE(syntax.find("joint.csv: --force 'TorqueCur1 -': ends where a column, a number or '(' was expected"), std::string::npos)
      << syntax;
  EXPECT_NE(error_of([&] { evaluate_column_expression(d, "(Torque1 * 2", "--force"); }).find("is not closed"), std::string::npos);
  EXPECT_NE(error_of([&] { evaluate_column_expression(d, "`Current [A] * 2", "--force"); }).find("backquote at character 1 is not closed"),
            std::string::npos);
  EXPECT_NE(error_of([&] { evaluate_column_expression(d, "Torque1 Torque1", "--force"); }).find("unexpected 'T' at character 9"),
            std::string::npos);
  EXPECT_NE(error_of([&] { evaluate_column_expression(d, "Torque1 ^ 2", "--force"); }).find("unexpected '^' at character 9"),
            std::string::npos);
  // A division by zero names the file's line of the sample.
  Dataset z = joint_log();
  z.column("Torque1")[1] = 0.0;
  EXPECT_EQ(error_of([&] { evaluate_column_expression(z, "TorqueCur1 / Torque1", "--force"); }),
            "joint.csv: line 3: --force 'TorqueCur1 / Torque1' is inf (a division by zero?); expected a finite number");
  // A non-finite sample of a column it uses is named as finite_column names it.
  z.column("Torque1")[2] = std::nan("");
  EXPECT_NE(error_of([&] { evaluate_column_expression(z, "TorqueCur1 - Torque1", "--force"); }).find("line 5, column 'Torque1'"),
            std::string::npos);
}

TEST(ColumnExpression, ErrorsCarryTheirCodes) {
  const Dataset d = joint_log();
  try {
    evaluate_column_expression(d, "Torque1 +", "--force");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), std::string(errc::option_invalid));
    EXPECT_EQ(e.fields().option, "--force");
  }
  try {
    evaluate_column_expression(d, "Torque9 + 1", "--force");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), std::string(errc::data_column_missing));
    EXPECT_EQ(e.fields().column, "Torque9");
  }
}

TEST(ColumnExpression, HostileNestingIsRefusedNotRecursed) {
  const Dataset d = joint_log();
  const std::string deep = std::string(100000, '(') + "Torque1" + std::string(100000, ')');
  EXPECT_NE(error_of([&] { evaluate_column_expression(d, deep, "--force"); }).find("characters long"), std::string::npos);
  const std::string nested = std::string(200, '(') + "Torque1" + std::string(200, ')');
  EXPECT_NE(error_of([&] { evaluate_column_expression(d, nested, "--force"); }).find("nested more than 64 levels"), std::string::npos);
  const std::string minus(300, '-');
  EXPECT_NE(error_of([&] { evaluate_column_expression(d, minus + "Torque1", "--force"); }).find("nested more than 64 levels"),
            std::string::npos);
}

}  // namespace
}  // namespace frictionlab
