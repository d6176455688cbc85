#include "Params.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sl {

namespace {
std::string formatNumber(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}
std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}
}  // namespace

std::string_view paramTypeName(ParamType type) {
  switch (type) {
    case ParamType::Bool:
      return "bool";
    case ParamType::Int:
      return "int";
    case ParamType::Float:
      return "float";
    case ParamType::Enum:
      return "enum";
  }
  return "?";
}

ParamDecl ParamDecl::withHelp(std::string text) && {
  help = std::move(text);
  return std::move(*this);
}

ParamDecl ParamDecl::withUniform(std::string name) && {
  uniform = std::move(name);
  return std::move(*this);
}

ParamDecl ParamDecl::asMemoryKnob() && {
  memoryKnob = true;
  return std::move(*this);
}

namespace {
/// What every named constructor sets: the names, the type and the default.
ParamDecl namedParam(std::string key, std::string label, std::string group, ParamType type,
                     double defaultValue) {
  return {.key = std::move(key),
          .label = std::move(label),
          .group = std::move(group),
          .type = type,
          .defaultValue = defaultValue};
}

ParamDecl numberParam(std::string key, std::string label, std::string group, ParamType type,
                      double defaultValue, ParamRange range) {
  ParamDecl d = namedParam(std::move(key), std::move(label), std::move(group), type, defaultValue);
  d.minValue = range.min;
  d.maxValue = range.max;
  d.step = range.step;
  return d;
}
}  // namespace

ParamDecl switchParam(std::string key, std::string label, std::string group, bool on) {
  ParamDecl d =
      namedParam(std::move(key), std::move(label), std::move(group), ParamType::Bool, on ? 1 : 0);
  d.step = 1;
  return d;
}

ParamDecl choiceParam(std::string key, std::string label, std::string group,
                      std::vector<std::string> names, int defaultIndex) {
  ParamDecl d =
      namedParam(std::move(key), std::move(label), std::move(group), ParamType::Enum, defaultIndex);
  d.maxValue = double(names.size()) - 1.0;
  d.step = 1;
  d.enumNames = std::move(names);
  return d;
}

ParamDecl intParam(std::string key, std::string label, std::string group, int defaultValue,
                   ParamRange range) {
  return numberParam(std::move(key), std::move(label), std::move(group), ParamType::Int,
                     defaultValue, range);
}

ParamDecl floatParam(std::string key, std::string label, std::string group, double defaultValue,
                     ParamRange range) {
  return numberParam(std::move(key), std::move(label), std::move(group), ParamType::Float,
                     defaultValue, range);
}

const ParamDecl* memoryKnob(const std::vector<ParamDecl>& decls) {
  for (const ParamDecl& d : decls)
    if (d.memoryKnob) return &d;
  return nullptr;
}

std::string describeRange(const ParamDecl& decl) {
  switch (decl.type) {
    case ParamType::Bool:
      return "on|off";
    case ParamType::Enum: {
      std::string s;
      for (size_t i = 0; i < decl.enumNames.size(); ++i) s += (i ? "|" : "") + decl.enumNames[i];
      return s;
    }
    default:
      return formatNumber(decl.minValue) + ".." + formatNumber(decl.maxValue);
  }
}

ParamSet::ParamSet(std::vector<ParamDecl> decls) : decls_(std::move(decls)) {
  for (const ParamDecl& d : decls_) {
    if (d.type == ParamType::Enum) {
      if (d.enumNames.empty()) throw std::logic_error("enum parameter without names: " + d.key);
    }
    if (values_.count(d.key)) throw std::logic_error("parameter declared twice: " + d.key);
    values_[d.key] = d.defaultValue;
  }
}

const ParamDecl* ParamSet::find(std::string_view key) const {
  for (const ParamDecl& d : decls_)
    if (d.key == key) return &d;
  return nullptr;
}

double ParamSet::get(std::string_view key) const {
  auto it = values_.find(key);
  if (it == values_.end()) throw std::out_of_range("unknown parameter '" + std::string(key) + "'");
  return it->second;
}

std::optional<std::string> ParamSet::set(std::string_view key, double value) {
  const ParamDecl* d = find(key);
  if (!d) {
    std::string known;
    for (const ParamDecl& k : decls_) known += (known.empty() ? "" : ", ") + k.key;
    return "unknown parameter '" + std::string(key) +
           "' (known: " + (known.empty() ? std::string("none") : known) + ")";
  }
  if (!std::isfinite(value)) return "parameter '" + d->key + "': value is not a finite number";
  double lo = d->minValue, hi = d->maxValue;
  if (d->type == ParamType::Bool) lo = 0, hi = 1;
  if (d->type == ParamType::Enum) lo = 0, hi = static_cast<double>(d->enumNames.size() - 1);
  if (d->type != ParamType::Float && value != std::floor(value))
    return "parameter '" + d->key + "' takes " +
           (d->type == ParamType::Int ? std::string("an integer") : describeRange(*d)) + ", got " +
           formatNumber(value);
  if (value < lo || value > hi)
    return "parameter '" + d->key + "' = " + formatNumber(value) + " is out of range " +
           describeRange(*d);
  double& slot = values_.find(key)->second;
  if (slot != value) {
    slot = value;
    ++revision_;
  }
  return std::nullopt;
}

std::optional<std::string> ParamSet::setFromString(std::string_view key, std::string_view text) {
  const ParamDecl* d = find(key);
  if (!d) return set(key, 0.0);  // produces the "unknown parameter" message
  std::string t = lower(text);
  if (d->type == ParamType::Bool) {
    if (t == "on" || t == "true" || t == "yes" || t == "1") return set(key, 1.0);
    if (t == "off" || t == "false" || t == "no" || t == "0") return set(key, 0.0);
    return "parameter '" + d->key + "' takes on|off, got '" + std::string(text) + "'";
  }
  if (d->type == ParamType::Enum) {
    for (size_t i = 0; i < d->enumNames.size(); ++i)
      if (lower(d->enumNames[i]) == t) return set(key, static_cast<double>(i));
  }
  double v = 0;
  const char* b = text.data();
  const char* e = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(b, e, v);
  if (ec != std::errc() || ptr != e || text.empty())
    return "parameter '" + d->key + "' takes " + describeRange(*d) + ", got '" + std::string(text) +
           "'";
  return set(key, v);
}

std::optional<std::string> ParamSet::assign(std::string_view kv) {
  size_t eq = kv.find('=');
  if (eq == std::string_view::npos || eq == 0)
    return "expected KEY=VALUE, got '" + std::string(kv) + "'";
  return setFromString(kv.substr(0, eq), kv.substr(eq + 1));
}

void ParamSet::resetToDefaults() {
  for (const ParamDecl& d : decls_) (void)set(d.key, d.defaultValue);
}

void ParamSet::reset(std::string_view key) {
  if (const ParamDecl* d = find(key)) (void)set(key, d->defaultValue);
}

std::string ParamSet::format(std::string_view key) const {
  const ParamDecl* d = find(key);
  if (!d) return {};
  double v = get(key);
  if (d->type == ParamType::Bool) return v != 0 ? "on" : "off";
  if (d->type == ParamType::Enum) return d->enumNames.at(static_cast<size_t>(v));
  return formatNumber(v);
}

std::optional<std::string> checkPowerOfTwo(const ParamSet& params, std::string_view key) {
  const int v = params.getInt(key);
  if (v > 0 && (v & (v - 1)) == 0) return std::nullopt;
  const ParamDecl* d = params.find(key);
  return std::string(key) + " = " + std::to_string(v) + " must be a power of two" +
         (d ? " (" + describeRange(*d) + ")" : std::string());
}

bool enumIs(const ParamSet& params, std::string_view key, std::string_view name) {
  const ParamDecl* d = params.find(key);
  if (!d) return false;
  const int v = params.getInt(key);
  return v >= 0 && v < int(d->enumNames.size()) && d->enumNames[std::size_t(v)] == name;
}

}  // namespace sl
