#include "description/material/ogre_script.h"

#include <cctype>

#include "bullet_sim/errors.h"

namespace bullet_sim {
namespace {

struct Token {
  enum Kind { kWord, kOpen, kClose, kLineEnd };
  Kind kind;
  std::string text;
  int line;
};

/// Splits `text` into words, braces and line ends, dropping comments.
class Lexer {
 public:
  Lexer(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  std::vector<Token> tokens() {
    while (pos_ < text_.size()) step();
    return std::move(tokens_);
  }

 private:
  void step() {
    const char c = text_[pos_];
    if (c == '\n') {
      tokens_.push_back({Token::kLineEnd, "", line_++});
      ++pos_;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++pos_;
    } else if (text_.compare(pos_, 2, "//") == 0) {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else if (text_.compare(pos_, 2, "/*") == 0) {
      skipBlockComment();
    } else if (c == '{' || c == '}') {
      tokens_.push_back({c == '{' ? Token::kOpen : Token::kClose, std::string(1, c), line_});
      ++pos_;
    } else if (c == ':') {
      tokens_.push_back({Token::kWord, ":", line_});
      ++pos_;
    } else if (c == '"') {
      readQuoted();
    } else {
      readWord();
    }
  }

  void skipBlockComment() {
    const int start_line = line_;
    const std::size_t end = text_.find("*/", pos_ + 2);
    if (end == std::string::npos)
      throw LoadError(ogreScriptError(source_, start_line, "'/*' comment is never closed"));
    for (std::size_t i = pos_; i < end; ++i) line_ += text_[i] == '\n';
    pos_ = end + 2;
  }

  void readQuoted() {
    const std::size_t end = text_.find_first_of("\"\n", pos_ + 1);
    if (end == std::string::npos || text_[end] != '"')
      throw LoadError(ogreScriptError(source_, line_, "quote is never closed: '" +
                                                          text_.substr(pos_, end - pos_) + "'"));
    tokens_.push_back({Token::kWord, text_.substr(pos_ + 1, end - pos_ - 1), line_});
    pos_ = end + 1;
  }

  void readWord() {
    const std::size_t start = pos_;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (std::isspace(static_cast<unsigned char>(c)) || c == '{' || c == '}' || c == ':' ||
          c == '"' || text_.compare(pos_, 2, "//") == 0 || text_.compare(pos_, 2, "/*") == 0)
        break;
      ++pos_;
    }
    tokens_.push_back({Token::kWord, text_.substr(start, pos_ - start), line_});
  }

  const std::string& text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  int line_ = 1;
  std::vector<Token> tokens_;
};

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

/// Builds statements from the tokens, one nesting level per call of body().
class BlockParser {
 public:
  BlockParser(std::vector<Token> tokens, const std::string& source)
      : tokens_(std::move(tokens)), source_(source) {}

  std::vector<OgreScriptNode> topLevel() { return body(nullptr); }

 private:
  /// Statements up to the `}` closing `opened` (nullptr: up to the end of the text).
  std::vector<OgreScriptNode> body(const OgreScriptNode* opened) {
    std::vector<OgreScriptNode> nodes;
    for (;;) {
      skipLineEnds();
      if (pos_ == tokens_.size()) {
        if (!opened) return nodes;
        throw LoadError(ogreScriptError(source_, opened->line,
                                        "'" + joined(opened->words) + " {' is never closed"));
      }
      const Token& token = tokens_[pos_];
      if (token.kind == Token::kClose) {
        if (!opened) throw LoadError(ogreScriptError(source_, token.line, "'}' closes no block"));
        ++pos_;
        return nodes;
      }
      if (token.kind == Token::kOpen)
        throw LoadError(ogreScriptError(source_, token.line, "'{' without a block name"));
      nodes.push_back(statement());
    }
  }

  OgreScriptNode statement() {
    OgreScriptNode node;
    node.line = tokens_[pos_].line;
    while (pos_ < tokens_.size() && tokens_[pos_].kind == Token::kWord)
      node.words.push_back(tokens_[pos_++].text);
    const std::size_t after_words = pos_;
    skipLineEnds();
    if (pos_ < tokens_.size() && tokens_[pos_].kind == Token::kOpen) {
      ++pos_;
      node.is_block = true;
      node.children = body(&node);
    } else {
      pos_ = after_words;
    }
    return node;
  }

  void skipLineEnds() {
    while (pos_ < tokens_.size() && tokens_[pos_].kind == Token::kLineEnd) ++pos_;
  }

  std::vector<Token> tokens_;
  const std::string& source_;
  std::size_t pos_ = 0;
};

}  // namespace

std::string ogreScriptError(const std::string& source_path, int line, const std::string& what) {
  return source_path + ":" + std::to_string(line) + ": " + what;
}

std::vector<OgreScriptNode> parseOgreScript(const std::string& text,
                                            const std::string& source_path) {
  return BlockParser(Lexer(text, source_path).tokens(), source_path).topLevel();
}

}  // namespace bullet_sim
