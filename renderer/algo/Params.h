// Parameter declarations: every tunable value of ShadowLab is declared once here-style
// (key, label, group, default, range, help, the shader uniform it sets) and the UI panel,
// the command line (--set key=value), JSON presets, the shaders' uniform binding and the
// tests all read that one declaration. Write them with designated initialisers.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sl {

enum class ParamType { Bool, Int, Float, Enum };

struct ParamDecl {
  std::string key;    ///< dotted identifier, e.g. "blur.radius"
  std::string label;  ///< short human name for the UI
  std::string group;  ///< UI group box, e.g. "Shadow map"
  ParamType type = ParamType::Float;
  double defaultValue = 0.0;
  double minValue = 0.0;
  double maxValue = 1.0;
  double step = 0.0;                   ///< UI step (0: type default)
  std::vector<std::string> enumNames;  ///< for Enum: value i is enumNames[i]
  std::string help;                    ///< one or two sentences, shown as tooltip and by `list`
  /// The GLSL uniform this parameter sets, bound by bindParams (core/ParamBinding.h) to
  /// every program of the technique that declares it; empty when no shader reads the value
  /// as is (e.g. the C++ turns it into something else first). The uniform's GLSL type
  /// follows `type`: Float -> float, Int / Bool / Enum -> int. A name that none of the
  /// technique's programs declares makes the technique fail to create.
  std::string uniform;
  /// The one integer parameter the technique's memory grows with (a map's resolution, a
  /// pool's page count): what the split view's "Equal memory" searches. At most one per
  /// technique (checked by tests/cpu), and a GL test checks the growth for every technique.
  bool memoryKnob = false;

  /// The finishing touches of the named constructors below (switchParam, choiceParam,
  /// intParam, floatParam): the declaration with `help`, `uniform` or `memoryKnob` set.
  ParamDecl withHelp(std::string text) &&;
  ParamDecl withUniform(std::string name) &&;
  ParamDecl asMemoryKnob() &&;
};

/// A numeric parameter's range and UI step (0: the type's default step).
struct ParamRange {
  double min = 0.0;
  double max = 1.0;
  double step = 0.0;
};

/// Named constructors for the shapes a declaration comes in, so that one reads as a line and
/// its help: `intParam("fvsm.grid", "Tile grid n", "FVSM", 32, {1, 64, 1}).withHelp("…")`.
/// An on/off switch (Bool: 0..1, step 1) that starts `on` or off.
ParamDecl switchParam(std::string key, std::string label, std::string group, bool on);
/// A choice among `names` (Enum: value i is names[i], 0..names.size() - 1, step 1).
ParamDecl choiceParam(std::string key, std::string label, std::string group,
                      std::vector<std::string> names, int defaultIndex = 0);
/// A whole number in `range`.
ParamDecl intParam(std::string key, std::string label, std::string group, int defaultValue,
                   ParamRange range);
/// A real number in `range`.
ParamDecl floatParam(std::string key, std::string label, std::string group, double defaultValue,
                     ParamRange range);

/// The declaration marked `memoryKnob` (null when none is; the first when several are, which
/// tests/cpu refuses for every shipped technique).
const ParamDecl* memoryKnob(const std::vector<ParamDecl>& decls);

/// Human readable range, e.g. "64..16384", "0..1", "on|off", "pcf-none|pcf-3x3".
std::string describeRange(const ParamDecl& decl);
std::string_view paramTypeName(ParamType type);

/// A set of values for a list of declarations. Values are always inside their range:
/// every setter validates and returns an error message naming the key and the range.
class ParamSet {
 public:
  ParamSet() = default;
  explicit ParamSet(std::vector<ParamDecl> decls);

  const std::vector<ParamDecl>& decls() const { return decls_; }
  const ParamDecl* find(std::string_view key) const;
  bool has(std::string_view key) const { return find(key) != nullptr; }

  double get(std::string_view key) const;  ///< throws std::out_of_range for unknown keys
  int getInt(std::string_view key) const { return static_cast<int>(get(key)); }
  bool getBool(std::string_view key) const { return get(key) != 0.0; }

  /// Sets a value; returns an error message (and changes nothing) when the key is unknown,
  /// the value is not finite, out of range, or not an integer for Int/Enum/Bool.
  std::optional<std::string> set(std::string_view key, double value);
  /// Parses "true/false/on/off", numbers, or enum names. Same errors as set().
  std::optional<std::string> setFromString(std::string_view key, std::string_view text);
  /// Parses "key=value".
  std::optional<std::string> assign(std::string_view keyEqualsValue);

  void resetToDefaults();
  void reset(std::string_view key);
  /// Value formatted for humans / JSON ("on", "pcf-3x3", "1024", "0.25").
  std::string format(std::string_view key) const;
  /// Monotonic counter increased by every successful change (renderers watch it).
  unsigned revision() const { return revision_; }

  bool operator==(const ParamSet& other) const { return values_ == other.values_; }

 private:
  std::vector<ParamDecl> decls_;
  std::map<std::string, double, std::less<>> values_;
  unsigned revision_ = 0;
};

/// Whether the Enum parameter `key` of `params` is set to the value named `name` (false when
/// `params` has no such key or the enum no such name).
bool enumIs(const ParamSet& params, std::string_view key, std::string_view name);

/// For a technique's checkParams: "KEY = V must be a power of two (RANGE)" when the integer
/// parameter `key` of `params` is not one, else nothing.
std::optional<std::string> checkPowerOfTwo(const ParamSet& params, std::string_view key);

}  // namespace sl
