#!/usr/bin/env bash
# Installs the npm packages pinned in web/package-lock.json into web/node_modules: three.js
# (the viewer page, bundled at build time by esbuild) and playwright-core (which drives
# Chromium in the viewer's test). `npm ci` installs exactly the lockfile, from the npm
# registry alone, and runs no package's install scripts (esbuild's binary comes as a
# package of its own). Idempotent: while web/node_modules is newer than the lockfile,
# nothing is done. Needs node 20 or later (playwright-core 1.65's engines).
set -euo pipefail
web=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if ! command -v npm >/dev/null 2>&1; then
  echo "web/install.sh: npm is missing (install node 20 or later with npm)" >&2
  exit 1
fi
stamp=$web/node_modules/.package-lock.json
# npm writes its record of what it installed last; newer than the lockfile, it is that.
if [[ $stamp -nt $web/package-lock.json ]]; then
  echo "web/install.sh: web/node_modules matches web/package-lock.json"
  exit 0
fi
cd "$web"
npm ci --ignore-scripts --no-audit --no-fund
