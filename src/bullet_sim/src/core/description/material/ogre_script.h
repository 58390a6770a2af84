#ifndef BULLET_SIM_CORE_OGRE_SCRIPT_H
#define BULLET_SIM_CORE_OGRE_SCRIPT_H

#include <string>
#include <vector>

namespace bullet_sim {

/// One statement of an OGRE script (.material, .program, .compositor): an attribute line
/// (`diffuse 1 0 0`) or a block (`pass name { ... }`), with the line it starts on.
struct OgreScriptNode {
  std::vector<std::string> words;  ///< the header or attribute words; never empty
  int line = 0;
  bool is_block = false;
  std::vector<OgreScriptNode> children;  ///< a block's statements
};

/// The top-level statements of OGRE script `text`, as OGRE's script lexer splits it:
/// statements end at a line end; `{`, `}` and `:` are tokens of their own; `"..."` is one
/// word; `//` and `/* */` are comments. A block's `{` may follow its header on the same
/// line or on a later one. Unbalanced braces, a `{` with no header, an unterminated
/// comment or quote throw LoadError naming `source_path`, the line and the text.
std::vector<OgreScriptNode> parseOgreScript(const std::string& text,
                                            const std::string& source_path);

/// `source_path:line: what`, the form of every OGRE script error.
std::string ogreScriptError(const std::string& source_path, int line, const std::string& what);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_OGRE_SCRIPT_H
