#pragma once
// GLSL source as tokens, every character kept: joining the tokens' text gives the source back, so a
// rewriter can change some tokens and leave the layout, comments and line count of the rest alone.
// Not a parser: it knows identifiers, numbers, comments, spaces, newlines and single punctuation, and
// which tokens sit on a preprocessor line. GL-free.

#include <string>
#include <string_view>
#include <vector>

namespace terrasol {

enum class GlslTokenKind { Identifier, Number, Punct, Space, Comment, Newline };

struct GlslToken {
  GlslTokenKind kind;
  std::string text;
  int line = 1;            // 1-based, where the token starts
  bool directive = false;  // on a line that starts with '#' (continuations included)

  bool is(std::string_view s) const { return text == s; }
  // Neither space, comment nor newline.
  bool significant() const {
    return kind != GlslTokenKind::Space && kind != GlslTokenKind::Comment && kind != GlslTokenKind::Newline;
  }
};

std::vector<GlslToken> tokenizeGlsl(std::string_view source);
std::string joinTokens(const std::vector<GlslToken>& tokens);

}  // namespace terrasol
