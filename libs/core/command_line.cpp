#include "core/command_line.hpp"

#include <cctype>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "core/errors.hpp"
#include "core/provenance.hpp"

namespace latmpm {

CommandLine::CommandLine(std::string tool, std::string manual)
    : tool_(std::move(tool)), manual_(std::move(manual)) {}

void CommandLine::option(const std::string& name, const std::string& metavar,
                         const std::string& help, const std::string& default_value) {
  declared_.push_back({name, metavar, help, default_value, Declared::value, false});
}
void CommandLine::repeated_option(const std::string& name, const std::string& metavar,
                                  const std::string& help) {
  declared_.push_back({name, metavar, help, "", Declared::repeated, false});
}
void CommandLine::flag(const std::string& name, const std::string& help) {
  declared_.push_back({name, "", help, "", Declared::boolean, false});
}
void CommandLine::alias(char letter, const std::string& name) {
  if (!find(name)) throw std::logic_error("alias for option '" + name + "' that was never declared");
  aliases_[letter] = name;
}
void CommandLine::positional(const std::string& name, const std::string& help, bool required) {
  declared_.push_back({name, "", help, "", Declared::positional, required});
}
void CommandLine::positional_list(const std::string& name, const std::string& help, bool required) {
  declared_.push_back({name, "", help, "", Declared::positional, required, true});
}

const CommandLine::Declared* CommandLine::find(const std::string& name) const {
  for (const auto& d : declared_)
    if (d.name == name) return &d;
  return nullptr;
}

std::string CommandLine::display(const std::string& name) const {
  const Declared* d = find(name);
  return (d && d->kind == Declared::positional) ? name : "--" + name;
}

void CommandLine::parse(int argc, const char* const* argv) {
  argv_.assign(argv, argv + argc);
  std::vector<const Declared*> positionals;
  for (const auto& d : declared_)
    if (d.kind == Declared::positional) positionals.push_back(&d);
  size_t next_positional = 0;
  bool options_done = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (!options_done && arg == "--") {
      options_done = true;
      continue;
    }
    if (!options_done && arg.size() >= 2 && arg[0] == '-' && arg[1] != '-' &&
        (arg.size() == 2 || arg[2] == '=')) {
      auto a = aliases_.find(arg[1]);
      if (a != aliases_.end()) arg = "--" + a->second + arg.substr(2);
    }
    if (!options_done && arg.size() > 2 && arg.compare(0, 2, "--") == 0) {
      std::string name = arg.substr(2), value;
      bool inline_value = false;
      if (auto eq = name.find('='); eq != std::string::npos) {
        value = name.substr(eq + 1);
        name = name.substr(0, eq);
        inline_value = true;
      }
      if (name == "help") {
        std::cout << help_text();
        throw HelpShown{};
      }
      if (name == "version") {
        std::cout << tool_ << " " << version_string() << "\n";
        throw HelpShown{};
      }
      const Declared* d = find(name);
      if (!d || d->kind == Declared::positional)
        throw UsageError("unknown option '--" + name + "' (see " + tool_ + " --help)");
      if (d->kind == Declared::boolean) {
        if (inline_value) throw UsageError("option '--" + name + "' takes no value");
        values_[name] = {"1"};
        continue;
      }
      if (!inline_value) {
        if (i + 1 >= argc) throw UsageError("option '--" + name + "' needs a value (" + d->metavar + ")");
        value = argv[++i];
      }
      if (d->kind == Declared::repeated)
        values_[name].push_back(value);
      else if (values_.count(name))
        throw UsageError("option '--" + name + "' given twice");
      else
        values_[name] = {value};
      continue;
    }
    if (!options_done && arg.size() > 1 && arg[0] == '-' && arg != "-" &&
        !(std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.'))
      throw UsageError("unknown option '" + arg + "' (options start with --; see " + tool_ + " --help)");
    if (next_positional >= positionals.size())
      throw UsageError("unexpected argument '" + arg + "' (see " + tool_ + " --help)");
    if (positionals[next_positional]->many) {  // takes every remaining argument
      values_[positionals[next_positional]->name].push_back(arg);
      continue;
    }
    values_[positionals[next_positional++]->name] = {arg};
  }
  for (; next_positional < positionals.size(); ++next_positional)
    if (positionals[next_positional]->required && !values_.count(positionals[next_positional]->name))
      throw UsageError("missing argument " + positionals[next_positional]->name + " (see " + tool_ +
                       " --help)");
}

bool CommandLine::given(const std::string& name) const {
  if (!find(name)) throw std::logic_error("option '" + name + "' was never declared");
  return values_.count(name) > 0;
}

std::string CommandLine::text(const std::string& name) const {
  const Declared* d = find(name);
  if (!d) throw std::logic_error("option '" + name + "' was never declared");
  auto it = values_.find(name);
  return it != values_.end() ? it->second.back() : d->default_value;
}

std::vector<std::string> CommandLine::all(const std::string& name) const {
  if (!find(name)) throw std::logic_error("option '" + name + "' was never declared");
  auto it = values_.find(name);
  return it != values_.end() ? it->second : std::vector<std::string>{};
}

double CommandLine::quantity(const std::string& name, const Dimension& expected) const {
  return parse_quantity(text(name), expected, display(name), "");
}

long CommandLine::integer(const std::string& name) const {
  std::string t = text(name);
  char* end = nullptr;
  long v = std::strtol(t.c_str(), &end, 10);
  if (t.empty() || *end != '\0') throw InputError(display(name), "", "'" + t + "' is not a whole number");
  return v;
}

double CommandLine::number(const std::string& name) const {
  return parse_quantity(text(name), dimension::none, display(name), "");
}

std::string CommandLine::help_text() const {
  std::ostringstream os;
  os << manual_;
  if (!manual_.empty() && manual_.back() != '\n') os << "\n";
  os << "\nOptions:\n";
  for (const auto& d : declared_) {
    std::string head = d.kind == Declared::positional ? "  " + d.name + (d.many ? "..." : "")
                       : d.kind == Declared::boolean  ? "  --" + d.name
                                                      : "  --" + d.name + " " + d.metavar;
    for (const auto& [letter, name] : aliases_)
      if (name == d.name) head = "  -" + std::string(1, letter) + ", " + head.substr(2);
    os << head;
    if (head.size() < 30)
      os << std::string(30 - head.size(), ' ');
    else
      os << "\n" << std::string(30, ' ');
    os << d.help;
    if (!d.default_value.empty()) os << " [default: " << d.default_value << "]";
    if (d.kind == Declared::repeated) os << " (repeatable)";
    os << "\n";
  }
  os << "  --help                      this text\n  --version                   the version\n";
  // The statuses every tool shares (core/tool_main.hpp, docs/robustness.md).
  os << "\nExit status: 0 done, 1 usage, 2 bad input, 3 numerical failure, 4 internal error, 5 an output\n"
        "could not be written (disk full, closed pipe), 128+N stopped by signal N (130 Ctrl-C, 143\n"
        "SIGTERM). On failure: one line on stderr naming the problem, no partial output left.\n";
  return os.str();
}

std::string CommandLine::resolved() const {
  std::string out = tool_;
  std::vector<std::string> args{tool_};
  for (const auto& d : declared_) {
    auto it = values_.find(d.name);
    if (d.kind == Declared::positional) {
      if (it != values_.end()) {
        if (d.many)
          args.insert(args.end(), it->second.begin(), it->second.end());
        else
          args.push_back(it->second.back());
      }
    } else if (d.kind == Declared::boolean) {
      if (it != values_.end()) args.push_back("--" + d.name);
    } else if (it != values_.end()) {
      for (const auto& v : it->second) {
        args.push_back("--" + d.name);
        args.push_back(v);
      }
    } else if (!d.default_value.empty()) {
      args.push_back("--" + d.name);
      args.push_back(d.default_value);
    }
  }
  std::vector<const char*> ptrs;
  for (const auto& a : args) ptrs.push_back(a.c_str());
  return quoted_command_line(static_cast<int>(ptrs.size()), ptrs.data());
}

}  // namespace latmpm
