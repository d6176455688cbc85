"""The output policy of algo/OutputFile.h for the Python scripts.

Before the work: no output is an input of the run or another output (symbolic links
resolved, hard links compared by identity), none is a folder, a FIFO, a device or a socket,
and its folder exists or is created; a problem is one line on stderr naming the output and
the path, exit 2 (refuse). Writing: into a temporary file beside the output's resolved path,
renamed over it when complete, so a failure leaves the old file whole (a link is kept, its
target replaced) and no temporary file behind (write_atomically).
"""
import contextlib
import io
import os
import stat
import sys
import tempfile


def _identity(path):
    try:
        st = os.stat(path)
    except OSError:
        return None
    return (st.st_dev, st.st_ino)


def _same(a, b):
    ra, rb = os.path.realpath(a), os.path.realpath(b)
    ia = _identity(ra)
    return ra == rb or (ia is not None and ia == _identity(rb))


def refuse(message):
    print(f"{os.path.basename(sys.argv[0])}: {message}", file=sys.stderr)
    sys.exit(2)


def check_outputs(outputs, inputs=()):
    """outputs, inputs: (name, path) pairs, e.g. ("--svg", "out.svg"), ("the CSV 'a.csv'", "a.csv").
    Refuses (exit 2) the first output that breaks the policy; creates missing folders."""
    seen = []
    for name, path in outputs:
        resolved = os.path.realpath(path)
        try:
            mode = os.stat(resolved).st_mode
        except OSError:
            mode = None
        if mode is not None and not stat.S_ISREG(mode):
            kind = ("a folder" if stat.S_ISDIR(mode) else "a FIFO" if stat.S_ISFIFO(mode)
                    else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
                    else "a socket" if stat.S_ISSOCK(mode) else "not a regular file")
            refuse(f"{name} '{path}' is {kind}, not a regular file "
                   "(refused: outputs are regular files)")
        for in_name, in_path in inputs:
            if _same(resolved, in_path):
                refuse(f"{name} '{path}' is the same file as {in_name} "
                       "(the input would be overwritten)")
        for out_name, out_path in seen:
            if _same(resolved, out_path):
                refuse(f"{name} '{path}' is the same file as {out_name} "
                       "(one would overwrite the other)")
        folder = os.path.dirname(resolved)
        if os.path.exists(folder) and not os.path.isdir(folder):
            refuse(f"{name}: '{folder}' is not a folder")
        try:
            os.makedirs(folder, exist_ok=True)
        except OSError as e:
            refuse(f"{name}: cannot create the folder '{folder}' ({e.strerror})")
        if not os.access(folder, os.W_OK):
            refuse(f"{name}: cannot write in the folder '{folder}'")
        seen.append((f"{name} '{path}'", path))


def write_atomically(path, text):
    """Writes text (UTF-8) to a temporary file beside path's resolved path and renames it over
    it. On any error the temporary file is removed and the old file is left as it was."""
    dest = os.path.realpath(path)
    fd, temp = tempfile.mkstemp(prefix=f".{os.path.basename(dest)}.",
                                dir=os.path.dirname(dest))
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temp, 0o666 & ~umask)
        os.replace(temp, dest)
    except BaseException:
        if os.path.exists(temp):
            os.unlink(temp)
        raise


def take_option(args, option):
    """Removes `option VALUE` from the list args; returns VALUE or None (a missing value is
    refused)."""
    if option not in args:
        return None
    i = args.index(option)
    if i + 1 >= len(args):
        refuse(f"{option}: missing its file")
    value = args[i + 1]
    del args[i:i + 2]
    return value


def print_or_write(path, produce):
    """Runs produce(), which prints; what it printed goes to path (written atomically), or to
    standard output when path is None. Nothing is written when produce() fails."""
    text = io.StringIO()
    with contextlib.redirect_stdout(text):
        produce()
    if path is None:
        sys.stdout.write(text.getvalue())
    else:
        write_atomically(path, text.getvalue())
