// The checks of options files before PETSc reads them (see command_line.hpp). PETSc 3.18 aborts
// with a banner on a missing, binary or malformed file and recurses without end into a file that
// includes itself; here every problem becomes one line naming the file.
#include "gradfric/core/command_line.hpp"

#include <yaml.h>

#include <sys/stat.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace gradfric {

namespace {

constexpr size_t kMaxFileBytes = 4u << 20;  // a scene is a few kB; 4 MiB is not an options file
constexpr size_t kMaxDepth = 16;            // nesting of -options_file inside options files

struct Problem {
  std::string what;  // empty: none
  explicit operator bool() const { return !what.empty(); }
};

// Index of the first byte that is not part of valid UTF-8, or npos.
size_t firstInvalidUtf8(const std::string& text) {
  size_t i = 0;
  while (i < text.size()) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (length == 0 || (length == 2 && c < 0xC2) || i + length > text.size()) return i;
    for (size_t k = 1; k < length; ++k)
      if ((static_cast<unsigned char>(text[i + k]) >> 6) != 0x2) return i;
    i += length;
  }
  return std::string::npos;
}

Problem readText(const std::string& path, std::string* text) {
  struct stat info;
  if (stat(path.c_str(), &info) != 0) return {std::strerror(errno)};
  if (S_ISDIR(info.st_mode)) return {"a directory, not an options file"};
  if (!S_ISREG(info.st_mode)) return {"not a regular file"};
  if (static_cast<size_t>(info.st_size) > kMaxFileBytes) return {"larger than 4 MiB, not an options file"};
  std::ifstream in(path, std::ios::binary);
  if (!in) return {std::string("not readable: ") + std::strerror(errno)};
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *text = buffer.str();
  const size_t nul = text->find('\0');
  if (nul != std::string::npos) return {"binary data (a NUL byte at offset " + std::to_string(nul) + "), not text"};
  const size_t bad = firstInvalidUtf8(*text);
  if (bad != std::string::npos) return {"not UTF-8 text (invalid byte at offset " + std::to_string(bad) + ")"};
  return {};
}

std::string canonical(const std::string& path) {
  char resolved[PATH_MAX];
  return realpath(path.c_str(), resolved) ? std::string(resolved) : path;
}

// PETSc's YAML reader wants a mapping (or nothing) at the top and scalar keys throughout.
Problem checkYamlNode(yaml_document_t* doc, yaml_node_t* node, bool top) {
  if (!node) return {"corrupt YAML document"};
  if (node->type == YAML_SCALAR_NODE) {
    if (top && node->data.scalar.length > 0)
      return {"YAML line " + std::to_string(node->start_mark.line + 1) + ": a mapping of options expected, found a scalar"};
    return {};
  }
  if (node->type == YAML_SEQUENCE_NODE) {
    if (top) return {"YAML line " + std::to_string(node->start_mark.line + 1) + ": a mapping of options expected, found a list"};
    for (yaml_node_item_t* item = node->data.sequence.items.start; item < node->data.sequence.items.top; ++item)
      if (Problem p = checkYamlNode(doc, yaml_document_get_node(doc, *item), false)) return p;
    return {};
  }
  for (yaml_node_pair_t* pair = node->data.mapping.pairs.start; pair < node->data.mapping.pairs.top; ++pair) {
    yaml_node_t* key = yaml_document_get_node(doc, pair->key);
    if (!key || key->type != YAML_SCALAR_NODE)
      return {"YAML line " + std::to_string(node->start_mark.line + 1) + ": option names must be plain scalars"};
    if (Problem p = checkYamlNode(doc, yaml_document_get_node(doc, pair->value), false)) return p;
  }
  return {};
}

Problem checkYaml(const std::string& text) {
  yaml_parser_t parser;
  if (!yaml_parser_initialize(&parser)) return {"out of memory while reading YAML"};
  yaml_parser_set_input_string(&parser, reinterpret_cast<const unsigned char*>(text.data()), text.size());
  Problem problem;
  while (!problem) {
    yaml_document_t doc;
    if (!yaml_parser_load(&parser, &doc)) {
      problem.what = "not valid YAML (line " + std::to_string(parser.problem_mark.line + 1) + ": " +
                     (parser.problem ? parser.problem : "parse error") + ")";
      break;
    }
    yaml_node_t* root = yaml_document_get_root_node(&doc);
    if (!root) {  // end of the stream
      yaml_document_delete(&doc);
      break;
    }
    problem = checkYamlNode(&doc, root, true);
    yaml_document_delete(&doc);
  }
  yaml_parser_delete(&parser);
  return problem;
}

struct Checker {
  std::vector<std::string> chain;  // canonical paths of the files being read, outermost first
  std::vector<std::string> shown;  // the same, as the user wrote them

  // option: "-options_file" or "-options_file_yaml"; where: "" or " (in a.opts line 3)".
  std::string check(const std::string& option, const std::string& path, const std::string& where) {
    auto fail = [&](const std::string& what) { return "invalid option " + option + " = " + path + where + ": " + what; };
    std::string text;
    if (Problem p = readText(path, &text)) return fail(p.what);
    if (option == "-options_file_yaml") {
      Problem p = checkYaml(text);
      return p ? fail(p.what) : "";
    }
    const std::string id = canonical(path);
    for (size_t k = 0; k < chain.size(); ++k)
      if (chain[k] == id) {
        std::string cycle;
        for (size_t j = k; j < shown.size(); ++j) cycle += shown[j] + " -> ";
        return fail("includes itself (" + cycle + path + ")");
      }
    if (chain.size() >= kMaxDepth) return fail("options files nested deeper than 16");
    chain.push_back(id);
    shown.push_back(path);
    std::string result = checkOptionsText(path, text);
    chain.pop_back();
    shown.pop_back();
    return result.empty() ? "" : result;
  }

  // PETSc's format: per line an option (-name [value]) or "alias -a -b"; # starts a comment.
  std::string checkOptionsText(const std::string& path, const std::string& text) {
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
      line = line.substr(0, line.find('#'));
      std::istringstream tokens(line);
      std::vector<std::string> words;
      for (std::string w; tokens >> w;) words.push_back(w);
      if (words.empty()) continue;
      const std::string where = " (in " + path + " line " + std::to_string(number) + ")";
      const std::string& first = words[0];
      const size_t start = first.rfind("--", 0) == 0 ? 2 : 1;
      const bool option = first[0] == '-' && first.size() > start && std::isalpha(static_cast<unsigned char>(first[start]));
      if (!option && first != "alias")
        return "invalid option -options_file = " + path + ": line " + std::to_string(number) + " starts with '" +
               first + "', not with an option (-name value)";
      if ((first == "-options_file" || first == "-options_file_yaml")) {
        if (words.size() < 2) return "invalid option " + first + where + ": no file name given";
        std::string nested = check(first, words[1], where);
        if (!nested.empty()) return nested;
      }
    }
    return "";
  }
};

}  // namespace

std::string checkOptionFiles(int argc, char** argv) {
  Checker checker;
  for (int i = 1; i < argc; ++i) {
    const bool plain = std::strcmp(argv[i], "-options_file") == 0;
    const bool yaml = std::strcmp(argv[i], "-options_file_yaml") == 0;
    if (!plain && !yaml) continue;
    if (i + 1 >= argc || argv[i + 1][0] == '\0')
      return std::string("invalid option ") + argv[i] + ": no file name given";
    std::string problem = checker.check(argv[i], argv[i + 1], "");
    if (!problem.empty()) return problem;
    ++i;
  }
  return "";
}

}  // namespace gradfric
