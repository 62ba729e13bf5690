#!/usr/bin/env python3
"""GIMP .pat (header: size, version, width, height, bytes, 'GPAT', name; then raw pixels) -> PGM/PPM."""
import struct, sys
d = open(sys.argv[1], 'rb').read()
hs, ver, w, h, b = struct.unpack('>5I', d[:20])
assert d[20:24] == b'GPAT', 'not a GIMP pattern'
px = d[hs:hs + w * h * b]
if b in (2, 4):   # drop alpha
    px = bytes(px[i] for i in range(len(px)) if i % b != b - 1); b -= 1
open(sys.argv[2], 'wb').write(b'%s\n%d %d\n255\n' % (b'P5' if b == 1 else b'P6', w, h) + px)
print(sys.argv[1], w, h, b, d[24:hs].rstrip(b'\0').decode('utf-8', 'replace'))
