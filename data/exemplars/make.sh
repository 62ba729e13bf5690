#!/usr/bin/env bash
# Rebuilds the exemplar photographs of this folder from their Debian packages
# (see README): apt-get download, dpkg-deb -x, then pat2pnm.py (GIMP patterns)
# and oiiotool (openimageio-tools) for crops and scaling. Run from anywhere;
# needs network access to the Debian archive, python3 and oiiotool.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
apt-get download gimp-data=2.10.34-1+deb12u10 mate-backgrounds=1.26.0-1
dpkg-deb -x gimp-data_*.deb g
dpkg-deb -x mate-backgrounds_*.deb m
pat=g/usr/share/gimp/2.0/patterns
for p in Stone/granite1 Stone/Craters Paper/crinklepaper Stone/stone33; do
  python3 "$here/pat2pnm.py" "$pat/$p.pat" "$(basename "$p").pnm"
done
oiiotool granite1.pnm -d uint8 -o "$here/granite.png"
oiiotool Craters.pnm -d uint8 -o "$here/craters.png"
oiiotool crinklepaper.pnm -d uint8 -o "$here/crinklepaper.png"
oiiotool stone33.pnm -d uint8 -o "$here/stone.png"
# Storm.jpg is 1920 x 1280; the clouds above the horizon, 512 x 512 from
# (200, 150), halved (oiiotool's default resize filter) to 256 x 256.
oiiotool m/usr/share/backgrounds/mate/nature/Storm.jpg --cut 512x512+200+150 --resize 256x256 -d uint8 -o "$here/clouds.png"
