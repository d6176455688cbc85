#!/usr/bin/env bash
# A technique's id is spelled out only where the technique lives: its folders
# (renderer/techniques/<folder>/, shaders/<folder>/, the panels of its family under
# ui/panels/) and the two lists that name every technique (renderer/core/TechniqueRegistry.cpp,
# ui/panels/PanelRegistry.cpp). Anywhere else in product code (app/, ui/, renderer/), a quoted
# "<id>" is a special case for one technique that should be a declared property of its
# TechniqueInfo instead (baseline, firstScreen, unanalysedWarp, a publication it declares...),
# so that adding, renaming or removing a technique touches its folders and one line.
# The ids are read from the registry: a quoted id on an entry's line, or else the first string
# after `TechniqueInfo info{` in the folder of the class the entry names (its #include).
# Comments do not count, nor the names of a parameter's choices (choiceParam: fvsm.warp's
# "lispsm" names the warp it selects, not the technique). See docs/developer/adding-a-technique.md.
# usage: technique_ids_in_folders.sh <repository root>
set -euo pipefail
root=$1
registry=renderer/core/TechniqueRegistry.cpp

# The panel folders of each technique folder (ui/panels/<panels>/); the others (analysis,
# common, light) draw what every technique publishes.
declare -A panelsOf=(
  [rtw]=rtw [perspective]=perspective [cascades]=partition [facepartition]=partition
  [cube]=omni [dual-paraboloid]=omni [spherical]=omni [rmsm]=pages [asm]=pages
  [fvsm]=fvsm [virtual-tiled]=fvsm
)
# Files that name something else with the same words: the split schemes (uniform, log,
# practical) and Lloyd et al.'s storage schemes, named after the techniques whose storage
# they model (`shadowlab-cli storage --scheme uniform|psm|lispsm|tsm|cascades|face`).
exempt=(renderer/algo/partition/Splits.cpp renderer/algo/partition/StorageFactor.cpp
        app/cli/Storage.cpp)

# id<TAB>folder for every registry entry.
mapfile -t pairs < <(perl -ne '
  BEGIN { ($root, $reg) = @ARGV[0, 1]; @ARGV = ("$root/$reg"); }
  if (m{#include "techniques/([^/"]+)/(\w+)\.h"}) { $folder{$2} = $1; next; }
  next unless /\b(?:entry|\w+Entry)\s*</ && !/^\s*(?:TechniqueEntry|template)/;
  my $line = $_;
  my ($class) = grep { $line =~ /\b$_\b/ } sort keys %folder;
  die "technique_ids_in_folders.sh: no technique class on registry line: $_" unless $class;
  my $f = $folder{$class};
  my $id;
  if (/"([^"]+)"/) { $id = $1; }
  else {
    local $/;
    for my $src (glob("$root/renderer/techniques/$f/*.cpp")) {
      open(my $h, "<", $src) or die; my $text = <$h>;
      if ($text =~ /TechniqueInfo\s+info\s*\{\s*"([^"]+)"/) { $id = $1; last; }
    }
  }
  die "technique_ids_in_folders.sh: no id for $class in renderer/techniques/$f/" unless $id;
  print "$id\t$f\n";
' "$root" "$registry")
if (( ${#pairs[@]} < 10 )); then
  echo "FAIL: read only ${#pairs[@]} technique ids from $registry"
  exit 1
fi

# Every quoted string of product code that is exactly an id, outside comments:
# file<TAB>line<TAB>id.
declare -A folderOf=()
for p in "${pairs[@]}"; do folderOf[${p%%$'\t'*}]=${p#*$'\t'}; done
fail=0
checked=0
while IFS=$'\t' read -r file lineno id; do
  checked=$((checked + 1))
  case $file in
    "$registry" | ui/panels/PanelRegistry.cpp) continue ;;
  esac
  for e in "${exempt[@]}"; do [[ $file == "$e" ]] && continue 2; done
  f=${folderOf[$id]}
  case $file in
    renderer/techniques/"$f"/* | shaders/"$f"/*) continue ;;
  esac
  if [[ -n ${panelsOf[$f]:-} && $file == ui/panels/"${panelsOf[$f]}"/* ]]; then continue; fi
  echo "FAIL: $file:$lineno spells the technique id \"$id\" outside renderer/techniques/$f/," \
       "shaders/$f/${panelsOf[$f]:+, ui/panels/${panelsOf[$f]}/} and the registries (declare" \
       "what it means on the technique's TechniqueInfo instead)"
  fail=1
done < <(cd "$root" && find app ui renderer -type f \( -name '*.cpp' -o -name '*.h' \) -print0 |
         sort -z | xargs -0 perl -ne '
  BEGIN { %id = map { $_ => 1 } split /,/, shift @ARGV; }
  my $code = $_;
  $code =~ s{"(?:[^"\\]|\\.)*"|(//.*)}{ defined $1 ? "" : $& }ge;   # drop // comments
  $code =~ s{choiceParam\(.*}{}; # a choice named after a method ("lispsm" warp), not an id
  while ($code =~ /"((?:[^"\\]|\\.)*)"/g) { print "$ARGV\t$.\t$1\n" if $id{$1}; }
  close ARGV if eof;
' "$(IFS=,; for p in "${pairs[@]}"; do printf '%s,' "${p%%$'\t'*}"; done)")

if ((fail)); then exit 1; fi
echo "PASS: ${#pairs[@]} technique ids, $checked quoted uses, all in their own folders or the registries"
