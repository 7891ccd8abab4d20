#!/usr/bin/env bash
# Fetches the test data the project does not commit: the Stanford bunny as
# the npm package `bunny` ships it (public domain), into DIR/bunny/index.js.
# Exit status: 0 when the data is there, 3 when npm is missing and cannot be
# installed (the bunny tests then report as skipped), 1 when npm is there but
# the fetch failed (no network, registry error): the callers that need the
# data (scripts/test.sh) fail then.
set -euo pipefail
dest="$1/bunny"
[ -f "$dest/index.js" ] && exit 0
if ! command -v npm >/dev/null; then
  echo "fetch-data: npm is missing, installing it" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  if ! DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq npm >/dev/null; then
    echo "fetch-data: npm could not be installed" >&2
    exit 3
  fi
fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
if ! (cd "$tmp" && timeout 120 npm pack --silent bunny@1.0.1 >"$tmp/npm.log" 2>&1 &&
      tar xzf bunny-1.0.1.tgz); then
  echo "fetch-data: npm is there but could not fetch bunny@1.0.1:" >&2
  tail -n 20 "$tmp/npm.log" >&2 || true
  exit 1
fi
mkdir -p "$dest"
cp "$tmp/package/index.js" "$dest/index.js"
