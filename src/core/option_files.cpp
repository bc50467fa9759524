// The command line settled before PETSc reads it (see command_line.hpp). PETSc 3.18 aborts with a
// banner on a missing, binary or malformed options file, recurses without end into a file that
// includes itself, skips stray words silently and reads a nested file from the working directory;
// here every problem becomes one line naming the option or the file, and the files are expanded in
// place so that their relative paths are their own folder's.
#include "gradfric/core/command_line.hpp"

#include <yaml.h>

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
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

// PETSc's rule (PetscOptionsValidKey): a dash, or two, then a letter, and not a number (-inf).
bool isKey(const std::string& word) {
  if (word.size() < 2 || word[0] != '-') return false;
  const char* key = word.c_str() + (word[1] == '-' ? 1 : 0);
  if (!std::isalpha(static_cast<unsigned char>(key[1]))) return false;
  char* end = nullptr;
  (void)std::strtod(key, &end);
  return end == key || *end == '_' || std::isalnum(static_cast<unsigned char>(*end));
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The folder a relative path inside the file `path` is taken from ("" for the working directory).
std::string folderOf(const std::string& path) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) return "";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string joinPath(const std::string& folder, const std::string& path) {
  if (folder.empty() || folder == "." || path.empty() || path[0] == '/') return path;
  return folder.back() == '/' ? folder + path : folder + "/" + path;
}

// A line's words as PETSc's tokenizer splits them: blanks separate, "a quoted value" is one word.
std::vector<std::string> lineWords(std::string line) {
  for (char& c : line)
    if (c == '\t' || c == '\r') c = ' ';
  std::vector<std::string> words;
  size_t i = 0;
  while (true) {
    while (i < line.size() && line[i] == ' ') ++i;
    if (i >= line.size()) break;
    const char end = line[i] == '"' ? '"' : ' ';
    if (end == '"') ++i;
    const size_t stop = std::min(line.find(end, i), line.size());
    words.push_back(line.substr(i, stop - i));
    i = stop + 1;
  }
  return words;
}

bool isBoolean(const std::string& word) {
  static const char* const words[] = {"1", "0", "true", "false", "yes", "no", "on", "off", "intro"};
  for (const char* w : words)
    if (lower(word) == w) return true;
  return false;
}

// Checks and expands options files into one list of words, the way PETSc would insert them.
struct Expander {
  SettledCommandLine result;
  std::vector<std::string> chain;  // canonical paths of the files being read, outermost first
  std::vector<std::string> shown;  // the same, as resolved for the user
  std::vector<std::string> prefixes;           // -prefix_push stack
  std::map<std::string, std::string> aliases;  // alias lines: lower-case name -> its replacement

  // Words after an option's one value: PETSc skips them silently, so -ensemble_delta 0 0.2 would
  // run Delta = 0 alone.
  static std::string stray(const std::vector<std::string>& words, size_t i, const std::string& where) {
    size_t j = i;
    std::string extra, commas;
    for (; j < words.size() && !isKey(words[j]); ++j) {
      extra += " " + words[j];
      commas += "," + words[j];
    }
    if (i >= 2 && isKey(words[i - 2]) && !isKey(words[i - 1]))
      return "invalid option " + words[i - 2] + " = " + words[i - 1] + extra + where +
             ": allowed one value (the stray word" + (j - i > 1 ? "s" : "") + extra +
             " would be ignored; a list is comma-separated without spaces: " + words[i - 1] + commas + ")";
    return "invalid word '" + words[i] + "'" + (where.empty() ? " on the command line" : where) +
           ": allowed options (-name [value]) only";
  }

  std::string fullName(const std::string& key) const {
    std::string prefix;
    for (const auto& p : prefixes) prefix += p;
    return "-" + prefix + key.substr(key[1] == '-' ? 2 : 1);
  }

  // PETSc's insertion of a list of words (the command line, or one line of a file): an option,
  // then its value if the next word is not an option. folder: where the words come from.
  std::string words(const std::vector<std::string>& w, const std::string& folder, const std::string& where) {
    for (size_t i = 0; i < w.size();) {
      if (!isKey(w[i])) return stray(w, i, where);
      const std::string name = lower(w[i]);
      const bool valued = i + 1 < w.size() && !isKey(w[i + 1]);
      if (name == "-options_file" || name == "-options_file_yaml") {
        if (!valued || w[i + 1].empty()) return "invalid option " + w[i] + where + ": no file name given";
        std::string problem = file(name, joinPath(folder, w[i + 1]), where);
        if (!problem.empty()) return problem;
        i += 2;
        continue;
      }
      if (name == "-prefix_pop") {
        if (!prefixes.empty()) prefixes.pop_back();
      } else if (name == "-prefix_push" && valued) {
        prefixes.push_back(w[i + 1]);
      }
      const auto alias = aliases.find(name);
      const std::string key = alias == aliases.end() ? w[i] : alias->second;
      result.arguments.push_back(key);
      if (name == "-help" && valued && !isBoolean(w[i + 1])) {  // -help fem: PETSc knows no prefix
        result.helpFilter = w[i + 1][0] == '-' ? w[i + 1].substr(1) : w[i + 1];
      } else if (valued) {
        result.arguments.push_back(w[i + 1]);
      }
      result.folders[lower(fullName(key))] = folder;
      i += valued ? 2 : 1;
    }
    return "";
  }

  // option: "-options_file" or "-options_file_yaml"; where: "" or " (in a.opts line 3)".
  std::string file(const std::string& option, const std::string& path, const std::string& where) {
    auto fail = [&](const std::string& what) { return "invalid option " + option + " = " + path + where + ": " + what; };
    std::string text;
    if (Problem p = readText(path, &text)) return fail(p.what);
    if (option == "-options_file_yaml") {
      if (Problem p = checkYaml(text)) return fail(p.what);
      result.arguments.push_back(option);
      result.arguments.push_back(path);
      return "";
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
    std::string problem = optionsText(path, text);
    chain.pop_back();
    shown.pop_back();
    return problem;
  }

  // PETSc's format: per line an option (-name [value]) or "alias -a -b"; # starts a comment.
  std::string optionsText(const std::string& path, const std::string& text) {
    std::vector<std::vector<std::string>> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(lineWords(line.substr(0, line.find('#'))));
    for (size_t n = 0; n < lines.size(); ++n) {  // PETSc sets a file's aliases before its options
      const auto& w = lines[n];
      if (w.empty() || w[0] != "alias") continue;
      if (w.size() != 3 || !isKey(w[1]) || !isKey(w[2]))
        return "invalid option -options_file = " + path + ": line " + std::to_string(n + 1) +
               ": an alias line is 'alias -name -other_name'";
      aliases[lower(w[1])] = w[2];
    }
    for (size_t n = 0; n < lines.size(); ++n) {
      const auto& w = lines[n];
      if (w.empty() || w[0] == "alias") continue;
      if (!isKey(w[0]))
        return "invalid option -options_file = " + path + ": line " + std::to_string(n + 1) + " starts with '" + w[0] +
               "', not with an option (-name value)";
      std::string problem = words(w, folderOf(path), " (in " + path + " line " + std::to_string(n + 1) + ")");
      if (!problem.empty()) return problem;
    }
    return "";
  }
};

}  // namespace

namespace {

// PETSc also reads the words of PETSC_OPTIONS and, unless -skip_petscrc, the files ~/.petscrc,
// .petscrc and petscrc. It would skip a stray word in PETSC_OPTIONS silently and abort with its
// banner on one in a petscrc file: the same checks as the command line's, naming the source (the
// options themselves are left to PETSc to read).
std::string checkPetscSources(const std::vector<std::string>& commandLine) {
  if (const char* environment = std::getenv("PETSC_OPTIONS")) {
    Expander check;
    const std::string problem = check.words(lineWords(environment), "", " (in the environment's PETSC_OPTIONS)");
    if (!problem.empty()) return problem;
  }
  for (const auto& word : commandLine)
    if (lower(word) == "-skip_petscrc") return "";
  const char* home = std::getenv("HOME");
  for (const std::string& path : {std::string(home ? home : "") + "/.petscrc", std::string(".petscrc"), std::string("petscrc")}) {
    struct stat info {};
    if ((path[0] == '/' && !home) || stat(path.c_str(), &info) != 0) continue;
    Expander check;
    std::string text;
    if (Problem p = readText(path, &text)) return "invalid PETSc options file " + path + ": " + p.what;
    const std::string problem = check.optionsText(path, text);
    if (!problem.empty()) return problem;
  }
  return "";
}

}  // namespace

SettledCommandLine settleCommandLine(int argc, char** argv) {
  Expander expander;
  expander.result.arguments.push_back(argc > 0 ? argv[0] : "gradfric");
  const std::vector<std::string> words(argv + std::min(argc, 1), argv + argc);
  expander.result.problem = expander.words(words, "", "");
  if (expander.result.problem.empty()) expander.result.problem = checkPetscSources(words);
  return expander.result;
}

std::string checkOptionFiles(int argc, char** argv) { return settleCommandLine(argc, argv).problem; }

namespace {

struct Adopted {
  std::vector<std::string> original;
  std::string helpFilter;
  std::map<std::string, std::string> folders;
};

Adopted& adopted() {
  static Adopted a;
  return a;
}

}  // namespace

void adoptCommandLine(const SettledCommandLine& settled, int argc, char** argv) {
  adopted().original.assign(argv, argv + argc);
  adopted().helpFilter = settled.helpFilter;
  adopted().folders = settled.folders;
}

const std::vector<std::string>& originalArguments() { return adopted().original; }

const std::string& helpFilter() { return adopted().helpFilter; }

std::string resolveOptionPath(const std::string& fullName, const std::string& value) {
  const auto at = adopted().folders.find(lower(fullName));
  return at == adopted().folders.end() ? value : joinPath(at->second, value);
}

}  // namespace gradfric
