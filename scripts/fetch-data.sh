#!/usr/bin/env bash
# Fetches the test data the project does not commit: the Stanford bunny as
# the npm package `bunny` ships it (public domain), into DIR/bunny/index.js.
set -euo pipefail
dest="$1/bunny"
[ -f "$dest/index.js" ] && exit 0
if ! command -v npm >/dev/null; then
  echo "fetch-data: npm is missing, installing it" >&2
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq npm >/dev/null
fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && timeout 120 npm pack --silent bunny@1.0.1 >/dev/null 2>&1 && tar xzf bunny-1.0.1.tgz)
mkdir -p "$dest"
cp "$tmp/package/index.js" "$dest/index.js"
