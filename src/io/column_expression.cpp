#include "frictionlab/io/column_expression.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "frictionlab/error.hpp"
#include "io/error_place.hpp"
#include "frictionlab/io/columns.hpp"

namespace frictionlab {
namespace {

using detail::option_of;
using detail::row_number;

// Nesting deeper than this is refused rather than recursed into (a hostile expression cannot
// exhaust the stack); no real derived column comes near it.
constexpr int kMaxDepth = 64;
constexpr std::size_t kMaxLength = 4096;

bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.'; }

struct Node {
  enum Kind { number, name, negate, add, subtract, multiply, divide } kind = number;
  double value = 0;
  std::string text;  // the column or scalar name
  std::unique_ptr<Node> left, right;
};

// Recursive descent over the grammar of column_expression.hpp.
class Parser {
 public:
  Parser(const Dataset& data, const std::string& text, const std::string& role) : data_(data), text_(text), role_(role) {}

  std::unique_ptr<Node> parse() {
    if (text_.size() > kMaxLength) fail("is " + std::to_string(text_.size()) + " characters long; expected at most " + std::to_string(kMaxLength));
    auto n = expression(0);
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "' at character " + std::to_string(pos_ + 1) + "; expected an operator (+ - * /) or the end");
    return n;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    const std::string who = role_.empty() ? std::string() : role_ + " ";
    throw InputError(errc::option_invalid,
                     data_.where() + who + "'" + text_ + "': " + what +
                         " (an expression of columns: NAME, `NAME WITH SPACES`, numbers, + - * / and parentheses)",
                     {.file = data_.file, .option = option_of(role_), .value = text_});
  }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])) != 0) ++pos_;
  }

  bool take(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }

  static std::unique_ptr<Node> binary(Node::Kind kind, std::unique_ptr<Node> l, std::unique_ptr<Node> r) {
    auto n = std::make_unique<Node>();
    n->kind = kind;
    n->left = std::move(l);
    n->right = std::move(r);
    return n;
  }

  std::unique_ptr<Node> expression(int depth) {
    auto n = term(depth);
    for (;;) {
      if (take('+')) n = binary(Node::add, std::move(n), term(depth));
      else if (take('-')) n = binary(Node::subtract, std::move(n), term(depth));
      else return n;
    }
  }

  std::unique_ptr<Node> term(int depth) {
    auto n = factor(depth);
    for (;;) {
      if (take('*')) n = binary(Node::multiply, std::move(n), factor(depth));
      else if (take('/')) n = binary(Node::divide, std::move(n), factor(depth));
      else return n;
    }
  }

  std::unique_ptr<Node> factor(int depth) {
    if (depth > kMaxDepth) fail("is nested more than " + std::to_string(kMaxDepth) + " levels deep");
    skip_space();
    if (pos_ == text_.size()) fail("ends where a column, a number or '(' was expected");
    if (take('+')) return factor(depth + 1);
    if (take('-')) {
      auto n = std::make_unique<Node>();
      n->kind = Node::negate;
      n->left = factor(depth + 1);
      return n;
    }
    if (take('(')) {
      auto n = expression(depth + 1);
      if (!take(')')) fail("'(' at or before character " + std::to_string(pos_) + " is not closed");
      return n;
    }
    const char c = text_[pos_];
    auto n = std::make_unique<Node>();
    if (c == '`') {
      const auto end = text_.find('`', pos_ + 1);
      if (end == std::string::npos) fail("the backquote at character " + std::to_string(pos_ + 1) + " is not closed");
      n->kind = Node::name;
      n->text = text_.substr(pos_ + 1, end - pos_ - 1);
      if (n->text.empty()) fail("empty name `` at character " + std::to_string(pos_ + 1));
      pos_ = end + 1;
      return n;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '.') {
      const char* begin = text_.data() + pos_;
      const auto [ptr, ec] = std::from_chars(begin, text_.data() + text_.size(), n->value);
      if (ec != std::errc() || !std::isfinite(n->value)) fail("bad number at character " + std::to_string(pos_ + 1));
      pos_ += static_cast<std::size_t>(ptr - begin);
      return n;
    }
    if (name_char(c)) {
      const std::size_t start = pos_;
      while (pos_ < text_.size() && name_char(text_[pos_])) ++pos_;
      n->kind = Node::name;
      n->text = text_.substr(start, pos_ - start);
      return n;
    }
    fail("unexpected '" + std::string(1, c) + "' at character " + std::to_string(pos_ + 1) +
         "; expected a column, a number or '('; a name with spaces or operators goes between backquotes");
  }

  const Dataset& data_;
  const std::string& text_;
  const std::string& role_;
  std::size_t pos_ = 0;
};

class Evaluator {
 public:
  Evaluator(const Dataset& data, const std::string& text, const std::string& role) : data_(data), text_(text), role_(role) {}

  Eigen::ArrayXd operator()(const Node& n) const {
    switch (n.kind) {
      case Node::number: return Eigen::ArrayXd::Constant(data_.rows(), n.value);
      case Node::name: return value_of(n.text);
      case Node::negate: return -(*this)(*n.left);
      case Node::add: return (*this)(*n.left) + (*this)(*n.right);
      case Node::subtract: return (*this)(*n.left) - (*this)(*n.right);
      case Node::multiply: return (*this)(*n.left) * (*this)(*n.right);
      case Node::divide: return (*this)(*n.left) / (*this)(*n.right);
    }
    return {};
  }

 private:
  Eigen::ArrayXd value_of(const std::string& name) const {
    if (data_.has_column(name)) return finite_column(data_, name, role_ + " '" + text_ + "'").array();
    const auto s = data_.scalars.find(name);
    if (s != data_.scalars.end()) {
      if (!std::isfinite(s->second))
        throw InputError(errc::data_not_finite, data_.where() + role_ + " '" + text_ + "': the scalar '" + name + "' is not a finite number",
                         {.file = data_.file, .column = name, .option = option_of(role_), .value = text_});
      return Eigen::ArrayXd::Constant(data_.rows(), s->second);
    }
    throw InputError(errc::data_column_missing, data_.missing_column_message(name, role_ + " '" + text_ + "'"),
                     {.file = data_.file, .column = name, .option = option_of(role_), .value = text_});
  }

  const Dataset& data_;
  const std::string& text_;
  const std::string& role_;
};

}  // namespace

bool is_column_expression(const Dataset& data, const std::string& text) {
  if (data.has_column(text)) return false;
  return text.find_first_of("+-*/()`") != std::string::npos;
}

Eigen::VectorXd evaluate_column_expression(const Dataset& data, const std::string& expression, const std::string& role) {
  const auto tree = Parser(data, expression, role).parse();
  const Eigen::VectorXd out = Evaluator(data, expression, role)(*tree).matrix();
  for (Eigen::Index k = 0; k < out.size(); ++k) {
    if (!std::isfinite(out[k])) {
      char value[32];
      std::snprintf(value, sizeof value, "%g", out[k]);
      throw InputError(errc::data_not_finite,
                       data.where() + data.row_label(k) + ": " + (role.empty() ? std::string() : role + " ") + "'" + expression +
                           "' is " + value + " (a division by zero?); expected a finite number",
                       {.file = data.file, .row = row_number(data, k), .option = option_of(role), .value = expression});
    }
  }
  return out;
}

Eigen::VectorXd finite_signal(const Dataset& data, const std::string& name_or_expression, const std::string& role) {
  if (is_column_expression(data, name_or_expression)) return evaluate_column_expression(data, name_or_expression, role);
  return finite_column(data, name_or_expression, role);
}

}  // namespace frictionlab
