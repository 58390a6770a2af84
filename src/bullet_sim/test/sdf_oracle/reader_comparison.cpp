#include "reader_comparison.h"

#include <fstream>
#include <sstream>

#include "bullet_sim/errors.h"
#include "description/sdf/sdf_reader.h"
#include "dom_compare.h"
#include "oracle_access.h"

namespace bullet_sim_test {

using bullet_sim::LoadError;

namespace {

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += (out.empty() ? "" : "; ") + l;
  return out;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::string builtinModelsDir() { return BULLET_SIM_BUILTIN_MODELS_DIR; }

bullet_sim::UriResolver resolverFor(const CorpusFile& file) {
  return bullet_sim::UriResolver(bullet_sim::ResourcePaths{file.model_paths, {}});
}

bullet_sim::SdfDocument readOurs(const CorpusFile& file, std::vector<std::string>* warnings) {
  std::ifstream in(file.path);
  if (!in) throw LoadError(file.path + ": cannot be opened");
  std::stringstream text;
  text << in.rdbuf();
  const auto doc =
      bullet_sim::parseSdfXml(text.str(), file.path, endsWith(file.path, ".world") ? "world" : "model");
  return bullet_sim::readSdf(*doc, file.path, file.path, resolverFor(file), warnings);
}

Comparison compareReaders(const CorpusFile& file) {
  Comparison out;
  std::optional<bullet_sim::SdfDocument> ours;
  std::string our_error;
  try {
    std::vector<std::string> warnings;
    ours = readOurs(file, &warnings);
  } catch (const LoadError& e) {
    our_error = e.what();
  }
  const OracleResult theirs = oracleReading(file);
  const bullet_sim::SdfDocument& doc = theirs.document;
  const bool they_refuse = !theirs.errors.empty() || (!doc.world && !doc.model && !doc.light);
  const std::string their_error =
      theirs.errors.empty() ? "nothing read" : joined(theirs.errors);
  if (!ours && they_refuse) {
    out.both_refuse = true;
    out.note = "both refuse it: ours: " + our_error + " | libsdformat: " + their_error;
  } else if (!ours) {
    out.differences.push_back(file.path + ": ours refuses it (" + our_error +
                              "), libsdformat reads it");
  } else if (they_refuse && !knownRefusalOf(file.path).empty()) {
    out.note = "libsdformat 12 refuses it as expected (" + knownRefusalOf(file.path) +
               "), ours reads it";
  } else if (they_refuse) {
    out.differences.push_back(file.path + ": libsdformat refuses it (" + their_error +
                              "), ours reads it");
  } else {
    DomComparer cmp(file.path);
    compareDocuments(&cmp, *ours, doc, theirs.canonical_links);
    out.differences = cmp.differences();
    out.compared = true;
    if (!theirs.set_aside.empty()) {
      out.note = "libsdformat errors set aside: " + joined(theirs.set_aside);
    }
  }
  return out;
}

}  // namespace bullet_sim_test
