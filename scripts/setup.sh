#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Provision everything the kit needs, idempotently: Debian packages, a pinned
# Python venv, the west workspace in deps/, Zephyr's Python requirements and a
# toolchain check. Safe to run again: each step skips what is already in place.
set -euo pipefail

KIT_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
VENV="$KIT_ROOT/.venv"
WS="$KIT_ROOT/deps"

say() { printf '[setup] %s\n' "$*"; }
die() { printf '[setup] ERROR: %s\n' "$*" >&2; exit 1; }

DEBIAN_PACKAGES=(gcc-arm-none-eabi picolibc-arm-none-eabi libstdc++-arm-none-eabi-picolibc
  qemu-system-arm device-tree-compiler ninja-build gperf ccache googletest
  python3-venv git file g++ make chromium)

install_debian_packages() {
  local missing=()
  for p in "${DEBIAN_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && { say "Debian packages: all present"; return; }
  command -v apt-get >/dev/null || die "missing packages (${missing[*]}) and no apt-get: install them with your package manager"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  say "installing Debian packages: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null \
    || die "apt-get could not install: ${missing[*]}"
}

# Re-install a requirements set only when its files change (stamp = their hash).
pip_install_stamped() {
  local name=$1; shift
  local stamp="$VENV/.stamp-$name" hash
  hash=$(cat "$@" | sha256sum | cut -d' ' -f1)
  [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$hash" ] && { say "python ($name): up to date"; return; }
  local args=()
  for f in "$@"; do args+=(-r "$f"); done
  say "python ($name): installing"
  # --no-compile: Python compiles a module on its first import instead; pip
  # would compile every file of every package up front (a third of the kit's
  # install, 30 s against 20 s, most of it modules nothing here imports)
  "$VENV/bin/pip" install -q --no-compile "${args[@]}" || die "pip could not install $name requirements ($*)"
  echo "$hash" >"$stamp"
}

make_venv() {
  if [ ! -x "$VENV/bin/python" ]; then
    say "creating $VENV"
    python3 -m venv "$VENV" || die "python3 -m venv failed (install python3-venv)"
    "$VENV/bin/pip" install -q --upgrade pip
  fi
  pip_install_stamped kit "$KIT_ROOT/scripts/requirements.txt"
  # The kit's own tooling package (scripts/kittools: kit CLI, west kit), editable
  local stamp="$VENV/.stamp-kittools" hash
  hash=$(sha256sum "$KIT_ROOT/scripts/pyproject.toml" | cut -d' ' -f1)
  if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$hash" ]; then
    "$VENV/bin/pip" install -q --no-deps -e "$KIT_ROOT/scripts" || die "pip could not install the kit's tooling (scripts/)"
    echo "$hash" >"$stamp"
  fi
}

# The west workspace (topdir): the clone itself (.west/ here, upstreams in
# deps/, paths in west.yml, both ignored by git), or the workspace of another
# repository whose west.yml imports the kit (`path: .` and `import:
# path-prefix: <the kit's folder>`, docs/your-deployment.md): its west
# update puts the kit's upstreams in the kit's deps/ all the same.
IMPORTED_BY=""
init_workspace() {
  if [ -f "$KIT_ROOT/.west/config" ]; then
    return
  fi
  local dir
  dir=$(dirname "$KIT_ROOT")
  while [ "$dir" != "/" ] && [ -n "$dir" ]; do
    if [ -f "$dir/.west/config" ]; then
      IMPORTED_BY=$dir
      return
    fi
    dir=$(dirname "$dir")
  done
  mkdir -p "$KIT_ROOT/.west"
  printf '[manifest]\npath = .\nfile = west.yml\n\n[zephyr]\nbase = deps/zephyr\n' >"$KIT_ROOT/.west/config"
}

# In an importing workspace, west update is that workspace's: the kit only
# checks that it put the upstreams where the kit reads them
check_imported_upstreams() {
  local project
  for project in zephyr fprime fprime-baremetal fprime-zephyr; do
    [ -d "$WS/$project/.git" ] || [ -f "$WS/$project/.git" ] || die "the west workspace $IMPORTED_BY imports the kit,
  but $WS/$project is missing. Run west update there; its west.yml must import the kit with
    path: .
    import:
      path-prefix: $(realpath --relative-to="$IMPORTED_BY" "$KIT_ROOT")
  so that the kit's upstreams land in its deps/ (docs/your-deployment.md)."
  done
  say "west workspace: $IMPORTED_BY (its manifest imports the kit; its west update fetched the upstreams)"
}

west_update() {
  say "west update (pinned revisions from west.yml)"
  local log
  log=$(mktemp)
  if ! (cd "$KIT_ROOT" && "$VENV/bin/west" update --narrow -o=--depth=1 >"$log" 2>&1); then
    # Surface the URL git could not reach and the air-gapped fix.
    local url
    url=$(grep -oE "(https?|ssh|git)://[^ ']+" "$log" | head -1 || true)
    tail -5 "$log" >&2
    die "west update could not fetch ${url:-an upstream}.
  Online: check the network/proxy. Air-gapped: serve a local mirror of each upstream and map it once per machine:
    git config --global url.<mirror-path-or-url>.insteadOf <upstream-url>
  (see README, 'Air-gapped setup'). Nothing in the kit changes."
  fi
  rm -f "$log"
}

# Where an upstream's patches apply: its workspace copy (deps/<project>), or,
# for a Python package the venv installs from PyPI (fprime-gds), the folder
# its installed files are under (site-packages)
patch_target() {
  local project=$1 installed
  if [ -d "$WS/$project" ]; then
    printf '%s\n' "$WS/$project"
    return
  fi
  installed=$("$VENV/bin/python" -c 'import importlib.metadata as m, sys; print(m.distribution(sys.argv[1]).locate_file(""))' \
    "$project" 2>/dev/null) || die "a patch names '$project', which is neither in the workspace nor installed in $VENV"
  printf '%s\n' "$installed"
}

# Upstream fixes the kit needs, kept as small explained patches with the
# module glue of the upstream they fix (modules/<project>/patches/*.patch),
# applied to its copy (patch_target).
apply_patches() {
  local patch project target
  for patch in "$KIT_ROOT"/modules/*/patches/*.patch; do
    [ -f "$patch" ] || continue
    project=$(basename "$(dirname "$(dirname "$patch")")")
    target=$(patch_target "$project")
    if git -C "$target" apply --reverse --check "$patch" 2>/dev/null; then
      continue  # already applied
    fi
    git -C "$target" apply "$patch" \
      || die "patch $patch does not apply to $project: was its pin (west.yml, scripts/requirements.txt) changed?"
    say "patched $project: $(basename "$patch")"
  done
}

# F´'s unit tests build googletest from fprime/googletest, a git submodule that
# west does not fetch; Debian's googletest is the same release (1.12.1) as source.
provide_googletest() {
  local dst="$WS/fprime/googletest" src=/usr/src/googletest
  [ -f "$dst/CMakeLists.txt" ] && return
  [ -f "$src/CMakeLists.txt" ] || die "googletest sources not found at $src: install Debian's googletest"
  rmdir "$dst" 2>/dev/null || true
  [ -e "$dst" ] && die "$dst exists but holds no googletest: remove it and run setup again"
  ln -s "$src" "$dst"
  say "googletest: $dst -> $src"
}

# The toolchain the builds will use: app/toolchain.cmake's choice (the one
# rule; scripts/env.sh applies it too). It prints the default's settings,
# nothing when a toolchain is chosen already, and fails when there is none.
check_toolchain() {
  local choice root
  command -v qemu-system-arm >/dev/null || die "qemu-system-arm not found: install qemu-system-arm"
  choice=$("$VENV/bin/cmake" -P "$KIT_ROOT/app/toolchain.cmake") \
    || die "no toolchain (above): install Debian's gcc-arm-none-eabi, or set ZEPHYR_SDK_INSTALL_DIR"
  if [ -z "$choice" ]; then
    say "toolchain: ${ZEPHYR_TOOLCHAIN_VARIANT:-zephyr} (chosen: ZEPHYR_TOOLCHAIN_VARIANT=${ZEPHYR_TOOLCHAIN_VARIANT:-}" \
      "ZEPHYR_SDK_INSTALL_DIR=${ZEPHYR_SDK_INSTALL_DIR:-}), $(qemu-system-arm --version | head -1)"
    return
  fi
  root=$(printf '%s\n' "$choice" | sed -n 's/^GNUARMEMB_TOOLCHAIN_PATH=//p')
  [ -f "$root/lib/picolibc/arm-none-eabi/picolibc.specs" ] \
    || die "picolibc for arm-none-eabi not found under $root: install picolibc-arm-none-eabi"
  say "toolchain: $("$root/bin/arm-none-eabi-gcc" --version | head -1) (gnuarmemb), $(qemu-system-arm --version | head -1)"
}

install_debian_packages
make_venv
init_workspace
if [ -n "$IMPORTED_BY" ]; then
  check_imported_upstreams
else
  west_update
fi
apply_patches
provide_googletest
pip_install_stamped zephyr "$WS/zephyr/scripts/requirements-base.txt" \
  "$WS/zephyr/scripts/requirements-build-test.txt" "$WS/zephyr/scripts/requirements-run-test.txt"
check_toolchain
say "ready: workspace $WS"
