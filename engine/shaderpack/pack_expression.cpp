#include "shaderpack/pack_expression.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.h"

namespace terrasol {

struct PackExpression::Node {
  enum class Kind { Number, Name, Unary, Binary, Call } kind = Kind::Number;
  float number = 0.0f;
  std::string name;  // a Name's or a Call's; an operator's
  std::vector<std::shared_ptr<Node>> children;
  // smooth(): the value it has reached.
  mutable std::optional<float> smoothed;
};

namespace {

using Node = PackExpression::Node;
using NodePtr = std::shared_ptr<Node>;

bool isNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.';
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& where) : text_(text), where_(where) {}

  NodePtr parse() {
    NodePtr e = binary(0);
    skipSpace();
    if (at_ != text_.size()) fail("unexpected '" + std::string(text_.substr(at_)) + "'");
    return e;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(where_ + ": '" + std::string(text_) + "': " + what);
  }
  void skipSpace() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])) != 0) ++at_;
  }
  // The binary operator at the cursor with its precedence level, not taken.
  std::optional<std::pair<std::string, int>> peekOperator() {
    skipSpace();
    static const std::pair<std::string_view, int> kOperators[] = {
        {"||", 0}, {"&&", 1}, {"==", 2}, {"!=", 2}, {"<=", 3}, {">=", 3}, {"<", 3},
        {">", 3},  {"+", 4},  {"-", 4},  {"*", 5},  {"/", 5},  {"%", 5}};
    for (const auto& [op, level] : kOperators)
      if (text_.compare(at_, op.size(), op) == 0) return std::pair{std::string(op), level};
    return std::nullopt;
  }
  NodePtr binary(int level) {
    NodePtr left = unary();
    for (;;) {
      const auto op = peekOperator();
      if (!op || op->second < level) return left;
      at_ += op->first.size();
      NodePtr right = binary(op->second + 1);
      left = std::make_shared<Node>(Node{Node::Kind::Binary, 0.0f, op->first, {left, right}, {}});
    }
  }
  NodePtr unary() {
    skipSpace();
    if (at_ < text_.size() && (text_[at_] == '!' || text_[at_] == '-')) {
      const std::string op(1, text_[at_++]);
      return std::make_shared<Node>(Node{Node::Kind::Unary, 0.0f, op, {unary()}, {}});
    }
    return primary();
  }
  NodePtr primary() {
    skipSpace();
    if (at_ >= text_.size()) fail("the expression ends early");
    if (text_[at_] == '(') {
      ++at_;
      NodePtr e = binary(0);
      skipSpace();
      if (at_ >= text_.size() || text_[at_] != ')') fail("missing ')'");
      ++at_;
      return e;
    }
    const std::size_t start = at_;
    while (at_ < text_.size() && isNameChar(text_[at_])) ++at_;
    const std::string_view word = text_.substr(start, at_ - start);
    if (word.empty()) fail("unexpected '" + std::string(text_.substr(at_, 1)) + "'");
    if (std::isdigit(static_cast<unsigned char>(word[0])) != 0 || word[0] == '.') {
      float v = 0.0f;
      const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
      if (ec != std::errc() || end != word.data() + word.size())
        fail("'" + std::string(word) + "' is not a number");
      return std::make_shared<Node>(Node{Node::Kind::Number, v, {}, {}, {}});
    }
    skipSpace();
    if (at_ < text_.size() && text_[at_] == '(') {
      ++at_;
      auto call = std::make_shared<Node>(Node{Node::Kind::Call, 0.0f, std::string(word), {}, {}});
      skipSpace();
      if (at_ < text_.size() && text_[at_] == ')') {
        ++at_;
        return call;
      }
      for (;;) {
        call->children.push_back(binary(0));
        skipSpace();
        if (at_ < text_.size() && text_[at_] == ',') {
          ++at_;
          continue;
        }
        if (at_ < text_.size() && text_[at_] == ')') {
          ++at_;
          return call;
        }
        fail("expected ',' or ')' in " + std::string(word) + "()");
      }
    }
    return std::make_shared<Node>(Node{Node::Kind::Name, 0.0f, std::string(word), {}, {}});
  }

  std::string_view text_;
  const std::string& where_;
  std::size_t at_ = 0;
};

class Evaluator {
 public:
  Evaluator(const PackEvaluation& context, const std::string& where) : context_(context), where_(where) {}

  PackValue operator()(const Node& n) const {
    switch (n.kind) {
      case Node::Kind::Number:
        return PackValue::of(n.number);
      case Node::Kind::Name:
        return name(n.name);
      case Node::Kind::Unary: {
        const float v = scalar(*n.children[0]);
        return PackValue::of(n.name == "!" ? (v == 0.0f ? 1.0f : 0.0f) : -v);
      }
      case Node::Kind::Binary:
        return PackValue::of(binary(n.name, scalar(*n.children[0]), *n.children[1]));
      case Node::Kind::Call:
        return call(n);
    }
    return {};
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw Error(where_ + ": " + what); }
  float scalar(const Node& n) const { return (*this)(n).scalar(); }

  PackValue name(const std::string& name) const {
    if (name == "true") return PackValue::of(1.0f);
    if (name == "false") return PackValue::of(0.0f);
    if (name == "pi") return PackValue::of(std::numbers::pi_v<float>);
    if (context_.lookUp)
      if (auto v = context_.lookUp(name)) return *v;
    // A vector's component: "cameraPosition.y".
    const auto dot = name.rfind('.');
    if (dot != std::string::npos && dot + 2 == name.size() && context_.lookUp) {
      if (auto v = context_.lookUp(std::string_view(name).substr(0, dot))) {
        const int i = std::string_view("xyzw").find(name.back()) != std::string_view::npos
                          ? static_cast<int>(std::string_view("xyzw").find(name.back()))
                          : static_cast<int>(std::string_view("rgba").find(name.back()));
        if (i >= 0 && i < v->size) return PackValue::of(v->v[i]);
      }
    }
    fail("unknown name '" + name + "'");
  }

  float binary(const std::string& op, float a, const Node& rightNode) const {
    // && and || do not evaluate their right side when the left decides.
    if (op == "&&") return a != 0.0f && scalar(rightNode) != 0.0f ? 1.0f : 0.0f;
    if (op == "||") return a != 0.0f || scalar(rightNode) != 0.0f ? 1.0f : 0.0f;
    const float b = scalar(rightNode);
    if (op == "+") return a + b;
    if (op == "-") return a - b;
    if (op == "*") return a * b;
    if (op == "/") return b == 0.0f ? 0.0f : a / b;  // as the GPU would not: no Inf into a uniform
    if (op == "%") return b == 0.0f ? 0.0f : std::fmod(a, b);
    const auto truth = [](bool t) { return t ? 1.0f : 0.0f; };
    if (op == "<") return truth(a < b);
    if (op == "<=") return truth(a <= b);
    if (op == ">") return truth(a > b);
    if (op == ">=") return truth(a >= b);
    if (op == "==") return truth(a == b);
    return truth(a != b);
  }

  PackValue call(const Node& n) const {
    const std::string& f = n.name;
    const std::size_t count = n.children.size();
    const auto arg = [&](std::size_t i) { return scalar(*n.children[i]); };
    const auto want = [&](std::size_t min, std::size_t max) {
      if (count < min || count > max)
        fail(f + "() takes " + std::to_string(min) + (max == min ? "" : " to " + std::to_string(max)) +
             " arguments, not " + std::to_string(count));
    };
    using Unary = float (*)(float);
    static const std::pair<std::string_view, Unary> kUnary[] = {
        {"sin", [](float x) { return std::sin(x); }},
        {"cos", [](float x) { return std::cos(x); }},
        {"asin", [](float x) { return std::asin(std::clamp(x, -1.0f, 1.0f)); }},
        {"acos", [](float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }},
        {"tan", [](float x) { return std::tan(x); }},
        {"atan", [](float x) { return std::atan(x); }},
        {"torad", [](float x) { return x * std::numbers::pi_v<float> / 180.0f; }},
        {"todeg", [](float x) { return x * 180.0f / std::numbers::pi_v<float>; }},
        {"abs", [](float x) { return std::abs(x); }},
        {"floor", [](float x) { return std::floor(x); }},
        {"ceil", [](float x) { return std::ceil(x); }},
        {"exp", [](float x) { return std::exp(x); }},
        {"frac", [](float x) { return x - std::floor(x); }},
        {"log", [](float x) { return x > 0.0f ? std::log(x) : 0.0f; }},
        {"round", [](float x) { return std::round(x); }},
        {"signum", [](float x) { return x > 0.0f   ? 1.0f
                                        : x < 0.0f ? -1.0f
                                                   : 0.0f; }},
        {"sqrt", [](float x) { return x > 0.0f ? std::sqrt(x) : 0.0f; }},
    };
    for (const auto& [name, fn] : kUnary)
      if (f == name) {
        want(1, 1);
        return PackValue::of(fn(arg(0)));
      }
    if (f == "atan2") return want(2, 2), PackValue::of(std::atan2(arg(0), arg(1)));
    if (f == "pow") return want(2, 2), PackValue::of(std::pow(std::abs(arg(0)), arg(1)));
    if (f == "fmod") return want(2, 2), PackValue::of(arg(1) == 0.0f ? 0.0f : std::fmod(arg(0), arg(1)));
    if (f == "min" || f == "max") {
      want(1, 64);
      float v = arg(0);
      for (std::size_t i = 1; i < count; ++i) v = f == "min" ? std::min(v, arg(i)) : std::max(v, arg(i));
      return PackValue::of(v);
    }
    if (f == "clamp") return want(3, 3), PackValue::of(std::clamp(arg(0), arg(1), std::max(arg(1), arg(2))));
    if (f == "between") return want(3, 3), PackValue::of(arg(0) >= arg(1) && arg(0) <= arg(2) ? 1.0f : 0.0f);
    if (f == "equals") return want(3, 3), PackValue::of(std::abs(arg(0) - arg(1)) <= arg(2) ? 1.0f : 0.0f);
    if (f == "in") {
      want(2, 64);
      const float x = arg(0);
      for (std::size_t i = 1; i < count; ++i)
        if (arg(i) == x) return PackValue::of(1.0f);
      return PackValue::of(0.0f);
    }
    if (f == "if") {
      // if(c1, v1, c2, v2, ..., else): the value of the first true condition.
      want(3, 64);
      if (count % 2 == 0) fail("if() takes conditions and values in pairs and a last value");
      for (std::size_t i = 0; i + 1 < count; i += 2)
        if (arg(i) != 0.0f) return (*this)(*n.children[i + 1]);
      return (*this)(*n.children[count - 1]);
    }
    if (f == "smooth") {
      // smooth([id,] value, [fadeUp, [fadeDown]]): moves towards the value, 1 - 1/e of the way in a
      // fade time (1 s by default).
      want(1, 4);
      const std::size_t first = count == 4 ? 1 : 0;
      const float target = arg(first);
      const float up = count > first + 1 ? arg(first + 1) : 1.0f;
      const float down = count > first + 2 ? arg(first + 2) : up;
      if (!n.smoothed) {
        n.smoothed = target;
      } else {
        const float fade = target > *n.smoothed ? up : down;
        const float k = fade <= 0.0f ? 1.0f : 1.0f - std::exp(-context_.frameTime / fade);
        n.smoothed = *n.smoothed + (target - *n.smoothed) * k;
      }
      return PackValue::of(*n.smoothed);
    }
    if (f == "vec2" || f == "vec3" || f == "vec4") {
      const int size = f[3] - '0';
      want(static_cast<std::size_t>(size), static_cast<std::size_t>(size));
      PackValue v{size, glm::vec4(0.0f)};
      for (int i = 0; i < size; ++i) v.v[i] = arg(static_cast<std::size_t>(i));
      return v;
    }
    fail("unknown function '" + f + "'");
  }

  const PackEvaluation& context_;
  const std::string& where_;
};

}  // namespace

PackExpression PackExpression::parse(std::string_view text, const std::string& where) {
  PackExpression e;
  e.root_ = Parser(text, where).parse();
  e.where_ = where;
  return e;
}

PackValue PackExpression::evaluate(const PackEvaluation& context) const {
  return Evaluator(context, where_)(*root_);
}

}  // namespace terrasol
