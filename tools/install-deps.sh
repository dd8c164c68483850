#!/bin/sh
# Install the Debian packages udec needs, only those missing. Runs apt-get as
# root (CI) or through sudo; does nothing when everything is present.
set -e
PACKAGES="gfortran cmake make pkg-config liblapack-dev libhdf5-dev libosmesa6-dev libpng-dev libedit-dev python3 valgrind"
missing=""
for p in $PACKAGES; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "Installing missing Debian packages:$missing"
if [ "$(id -u)" = 0 ]; then
  SUDO=""
elif command -v sudo >/dev/null 2>&1; then
  SUDO="sudo"
else
  echo "tools/install-deps.sh: not root and no sudo: run it as root (su -c 'sh tools/install-deps.sh')," >&2
  echo "or install as root: apt-get install$missing" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends $missing
