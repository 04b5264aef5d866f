#!/usr/bin/env bash
# Installs the npm packages pinned in web/package-lock.json into web/node_modules: three.js
# (the viewer page, bundled at build time by esbuild), playwright-core (which drives
# Chromium in the viewer's test) and the Khronos glTF validator (which checks every glTF
# file the tests export). `npm ci` installs exactly the lockfile, from the npm registry
# alone, each package's integrity checked, and runs no package's install scripts
# (esbuild's binary comes as a package of its own). Node.js and npm come from Debian's
# packages (nodejs, and npm where nodejs does not carry it) when no node is installed;
# playwright-core 1.65 asks for node 20 or later. Idempotent: while web/node_modules holds
# what the lockfile says (a copy of the lockfile npm ci installed is kept there), nothing
# is done. Run by .ci/install-deps.
set -euo pipefail
web=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

apt_install() {
  local as_root=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null 2>&1; then
      echo "web/install.sh: need root or sudo to install $*" >&2
      exit 1
    fi
    as_root=(sudo)
  fi
  echo "web/install.sh: installing $*"
  export DEBIAN_FRONTEND=noninteractive
  "${as_root[@]}" apt-get update -q
  "${as_root[@]}" apt-get install -y -q --no-install-recommends "$@"
}

command -v node >/dev/null 2>&1 || apt_install nodejs
command -v npm >/dev/null 2>&1 || apt_install npm

stamp=$web/node_modules/.installed-package-lock.json
if cmp -s "$stamp" "$web/package-lock.json"; then
  echo "web/install.sh: web/node_modules matches web/package-lock.json"
  exit 0
fi
cd "$web"
echo "web/install.sh: npm ci in web/ (node $(node --version))"
npm ci --ignore-scripts --no-audit --no-fund
cp package-lock.json "$stamp"
