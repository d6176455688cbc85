# shellcheck shell=bash
# The output policy of algo/OutputFile.h for the shell scripts (sourced, never run). Before the
# work: no output is an input of the run or another output (symbolic links resolved, hard links
# compared by identity), none is a folder, a FIFO, a device or a socket, and its folder exists
# or is created; each problem is one line on stderr naming the output and the path, exit 2.
# Writing: into a temporary file beside the output's resolved path, renamed over it when
# complete, so a failed or interrupted run leaves the old file whole (a link is kept, its
# target replaced). Sourcing installs an EXIT trap that removes unfinished temporary files; a
# script with an EXIT trap of its own calls output_cleanup in it.
#
#   output_input NAME PATH      an input of the run that no output may be (NAME: "the scene")
#   output_folder NAME DIR      DIR is (or becomes) a folder: refused when it is anything else
#   output_check NAME PATH      an output, checked against the inputs and the other outputs
#   output_temp PATH            OUTPUT_TEMP: a new temporary file for PATH (not a subshell:
#                               call it directly, then read $OUTPUT_TEMP)
#   output_commit TEMP PATH     renames TEMP over PATH's resolved path
#   output_write PATH CMD...    CMD's standard output into PATH, renamed only when CMD succeeds

_output_self=$(basename "$0")
_output_inputs=()       # "resolved path<TAB>name"
_output_outputs=()      # "resolved path<TAB>name"
_output_temps=()
OUTPUT_TEMP=""

_output_refuse() {
  echo "$_output_self: $*" >&2
  exit 2
}

# The identity of an existing file (device:inode), or nothing.
_output_identity() {
  stat -L -c '%d:%i' -- "$1" 2>/dev/null || true
}

output_input() {
  [[ -e $2 ]] || return 0
  _output_inputs+=("$(realpath -m -- "$2")"$'\t'"$1 '$2'")
}

output_folder() {
  local name=$1 dir=$2
  if [[ -e $dir && ! -d $dir ]]; then
    _output_refuse "$name '$dir' is not a folder (refused: outputs go into a folder)"
  fi
  mkdir -p -- "$dir" 2>/dev/null || _output_refuse "$name: cannot create the folder '$dir'"
  [[ -w $dir ]] || _output_refuse "$name: cannot write in the folder '$dir'"
}

# Refuses PATH as NAME when it is the same file as one of the recorded files ("what" says which
# list: input or output).
_output_against() {
  local name=$1 path=$2 resolved=$3 what=$4 entry other other_name id
  shift 4
  id=$(_output_identity "$resolved")
  for entry in "$@"; do
    other=${entry%%$'\t'*} other_name=${entry#*$'\t'}
    if [[ $other == "$resolved" || (-n $id && $id == "$(_output_identity "$other")") ]]; then
      if [[ $what == input ]]; then
        _output_refuse "$name '$path' is the same file as $other_name" \
          "(the input would be overwritten)"
      fi
      _output_refuse "$name '$path' is the same file as $other_name" \
        "(one would overwrite the other)"
    fi
  done
}

output_check() {
  local name=$1 path=$2 resolved kind=""
  resolved=$(realpath -m -- "$path")
  if [[ -d $resolved ]]; then kind="a folder"
  elif [[ -p $resolved ]]; then kind="a FIFO"
  elif [[ -b $resolved || -c $resolved ]]; then kind="a device"
  elif [[ -S $resolved ]]; then kind="a socket"
  elif [[ -e $resolved && ! -f $resolved ]]; then kind="not a regular file"
  fi
  [[ -z $kind ]] ||
    _output_refuse "$name '$path' is $kind, not a regular file (refused: outputs are regular files)"
  _output_against "$name" "$path" "$resolved" input "${_output_inputs[@]}"
  _output_against "$name" "$path" "$resolved" output "${_output_outputs[@]}"
  output_folder "$name" "$(dirname -- "$resolved")"
  _output_outputs+=("$resolved"$'\t'"$name '$path'")
}

output_temp() {
  local dest
  dest=$(realpath -m -- "$1")
  OUTPUT_TEMP=$(mktemp "$(dirname -- "$dest")/.$(basename -- "$dest").XXXXXX") || {
    echo "$_output_self: $1: cannot create a temporary file beside it" >&2
    return 1
  }
  _output_temps+=("$OUTPUT_TEMP")
}

output_commit() {
  local temp=$1 dest
  dest=$(realpath -m -- "$2")
  chmod "$(printf '%o' $((0666 & ~$(umask))))" -- "$temp" &&
    mv -fT -- "$temp" "$dest" || {
    rm -f -- "$temp"
    echo "$_output_self: $2: cannot write (the temporary file was not renamed)" >&2
    return 1
  }
}

output_write() {
  local target=$1 temp rc=0
  shift
  output_temp "$target" || return 1
  temp=$OUTPUT_TEMP
  "$@" >"$temp" || rc=$?
  if ((rc != 0)); then
    rm -f -- "$temp"
    return "$rc"
  fi
  output_commit "$temp" "$target"
}

output_cleanup() {
  local temp
  for temp in "${_output_temps[@]}"; do
    [[ ! -e $temp ]] || rm -f -- "$temp"
  done
  return 0
}

trap output_cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
