#!/usr/bin/env bash
# The system packages toonmesh's build, renderer and tests use, installed only when missing and
# only where that needs no guessing: as root, on Debian or Ubuntu (apt-get). Everywhere else it
# prints what to install and exits 0, so that the build goes on: smoothing and lines need no
# GPU, and rendering raises toonmesh.GpuUnavailableError naming what to install.
#
#   scripts/system-deps.sh          a rendering stack: Vulkan or EGL with GL (either is enough)
#   scripts/system-deps.sh --test   both stacks (the tests render on each) and Chromium, the
#                                   headless browser of the viewer's and the site's browser tests
#
# The stacks are Mesa's: lavapipe (Vulkan) and llvmpipe (GL through EGL), the software GPUs used
# where no real GPU is present (a real GPU's driver loads through the same libraries). The
# package names per distribution are in the README's Install section.
set -euo pipefail
test_mode=0
[ "${1:-}" = "--test" ] && test_mode=1

ldconfig_bin=$(command -v ldconfig || echo /sbin/ldconfig)
have_lib() { "$ldconfig_bin" -p 2>/dev/null | grep -q "$1"; }
have_file() { compgen -G "$1" >/dev/null; }

vulkan_ok() {
  have_lib 'libvulkan.so.1' && { have_file '/usr/share/vulkan/icd.d/*.json' || have_file '/etc/vulkan/icd.d/*.json'; }
}
egl_ok() {
  have_lib 'libEGL.so.1' && { have_lib 'libEGL_mesa.so.0' || have_lib 'libEGL_nvidia.so.0'; } &&
    { have_file '/usr/lib/*/dri/*_dri.so' || have_file '/usr/lib/dri/*_dri.so' || have_file '/usr/lib64/dri/*_dri.so'; }
}

# what is missing, by Debian's names
need=()
command -v cc >/dev/null 2>&1 || need+=(gcc)  # rustc links with it
if ! "${PYTHON:-python3}" -c 'import ensurepip, venv' 2>/dev/null; then
  need+=(python3-venv)
fi
vulkan_missing=0
egl_missing=0
vulkan_ok || vulkan_missing=1
egl_ok || egl_missing=1
if [ $test_mode -eq 1 ] || [ $((vulkan_missing & egl_missing)) -eq 1 ]; then
  [ $vulkan_missing -eq 1 ] && need+=(mesa-vulkan-drivers libvulkan1)
  if [ $test_mode -eq 1 ] && [ $egl_missing -eq 1 ]; then
    need+=(libegl1 libegl-mesa0 libgl1-mesa-dri)
  fi
fi
if [ $test_mode -eq 1 ] && ! command -v chromium >/dev/null 2>&1; then
  need+=(chromium)
fi
[ ${#need[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "toonmesh: installing ${need[*]}"
  export DEBIAN_FRONTEND=noninteractive
  # an automatic update on a fresh machine may hold the package lock: wait for it
  apt=(apt-get -o DPkg::Lock::Timeout=300 -o Acquire::Retries=3)
  if "${apt[@]}" update -qq && "${apt[@]}" install -y -qq --no-install-recommends "${need[@]}" >/dev/null; then
    exit 0
  fi
  echo "toonmesh: apt-get could not install them (above); the build goes on without them" >&2
fi

# without root, or not Debian: say what to install, and go on
debian_like=0
[ -r /etc/os-release ] && grep -qE '^(ID|ID_LIKE)=.*(debian|ubuntu)' /etc/os-release && debian_like=1
{
  if [ $test_mode -eq 1 ]; then
    echo "toonmesh: the tests need system packages that are missing (both rendering stacks, Chromium);"
  else
    echo "toonmesh: no Vulkan or EGL driver was found to render with;"
  fi
  echo "  the build goes on: smoothing and lines work, rendering raises GpuUnavailableError until one is there."
  if [ $debian_like -eq 1 ]; then
    echo "  install them with: sudo apt-get install -y ${need[*]}"
  else
    echo "  the packages for your distribution are in README.md, section Install (Debian's: ${need[*]})"
  fi
} >&2
exit 0
