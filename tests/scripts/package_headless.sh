#!/usr/bin/env bash
# scripts/package-headless.sh replaces its --out folder whole, so it refuses, in one line
# (exit 2) before the build, an --out that is a folder of other files, one that holds the
# source tree and a file; the folder is not deleted. A stub cmake (on PATH) records the
# build; ldd and strip are stubs too.
# usage: package_headless.sh <repository root> <output folder>
source "$(dirname "$0")/sandbox.bash" "$1" "$2/package_headless"
mkdir -p "$box/bin"
for tool in cmake ldd strip; do
  printf '#!/usr/bin/env bash\necho "%s $*" >>"%s/cli.calls"\n' "$tool" "$box" >"$box/bin/$tool"
  chmod +x "$box/bin/$tool"
done
export PATH=$box/bin:$PATH
mkdir -p "$box/photos"
echo "a photo" >"$box/photos/a.jpg"
expect_refused "--out is a folder of other files" \
  "--out '$box/photos' is a folder of other files (no bin/shadowlab-cli)" \
  root/scripts/package-headless.sh --out "$box/photos"
expect_content "--out is a folder of other files" "$box/photos/a.jpg" "a photo"
expect_refused "--out holds the sources" "--out '$box' holds '$box/root'" \
  root/scripts/package-headless.sh --out "$box"
expect_refused "--out is a file" "--out '$box/photos/a.jpg' is not a folder" \
  root/scripts/package-headless.sh --out "$box/photos/a.jpg"
expect_content "--out is a file" "$box/photos/a.jpg" "a photo"
finish
