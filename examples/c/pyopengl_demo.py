#!/usr/bin/env python3
"""pyopengl_demo.py - a headless PyOpenGL program on OSMesa (PYOPENGL_PLATFORM=osmesa).

Renders a small lit scene - a smooth sphere drawn from client-side vertex arrays, a flat-shaded
octahedron in immediate mode, a tiled floor with a spotlight on it, linear fog - into a buffer
it owns, and writes it as a PPM (or PNG, by the file name's ending). It needs PyOpenGL only (no
numpy, no PIL), so the same script runs on Mesa's libOSMesa.so.8 and on fixedgl's:

    PYOPENGL_PLATFORM=osmesa python3 pyopengl_demo.py out.ppm
    PYOPENGL_PLATFORM=osmesa fixedgl run -- python3 pyopengl_demo.py out.ppm

Usage: pyopengl_demo.py [OUT.ppm|OUT.png] [--size WxH]   (default pyopengl_demo.ppm, 320x240)
"""
import ctypes
import math
import os
import struct
import sys
import zlib

os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")

from OpenGL import GL  # noqa: E402  (the platform must be chosen first)
from OpenGL import osmesa  # noqa: E402


def sphere_arrays(radius, slices, stacks):
    """A triangle list of the sphere: (vertices, normals) as ctypes float arrays, count."""
    pts = []
    for i in range(stacks):
        t0 = math.pi * i / stacks - math.pi / 2
        t1 = math.pi * (i + 1) / stacks - math.pi / 2
        for j in range(slices):
            p0 = 2 * math.pi * j / slices
            p1 = 2 * math.pi * (j + 1) / slices
            quad = [(t0, p0), (t1, p0), (t1, p1), (t0, p1)]
            for a, b, c in ((0, 1, 2), (0, 2, 3)):
                for t, p in (quad[a], quad[b], quad[c]):
                    pts.append((math.cos(t) * math.cos(p), math.sin(t), -math.cos(t) * math.sin(p)))
    n = len(pts)
    normals = (ctypes.c_float * (3 * n))(*[c for p in pts for c in p])
    vertices = (ctypes.c_float * (3 * n))(*[radius * c for p in pts for c in p])
    return vertices, normals, n


def octahedron():
    """Eight faces, one normal each, in immediate mode."""
    tips = [(0, 1, 0), (0, -1, 0)]
    ring = [(1, 0, 0), (0, 0, -1), (-1, 0, 0), (0, 0, 1)]
    GL.glBegin(GL.GL_TRIANGLES)
    for top in tips:
        for k in range(4):
            a, b = ring[k], ring[(k + 1) % 4]
            if top[1] < 0:
                a, b = b, a
            n = [a[i] + b[i] + top[i] for i in range(3)]
            GL.glNormal3f(*n)  # NORMALIZE makes it unit length
            GL.glVertex3f(*top)
            GL.glVertex3f(*a)
            GL.glVertex3f(*b)
    GL.glEnd()


def floor():
    """A 12 x 12 tiled floor, each tile split into 3 x 3 quads for the spotlight's falloff."""
    GL.glNormal3f(0, 1, 0)
    for i in range(12):
        for j in range(12):
            c = (0.8, 0.8, 0.8, 1) if (i + j) % 2 else (0.35, 0.3, 0.45, 1)
            GL.glMaterialfv(GL.GL_FRONT, GL.GL_AMBIENT_AND_DIFFUSE, c)
            GL.glBegin(GL.GL_QUADS)
            for a in range(3):
                for b in range(3):
                    x, z, d = -6 + i + a / 3, -6 + j + b / 3, 1 / 3
                    GL.glVertex3f(x, 0, z)
                    GL.glVertex3f(x, 0, z + d)
                    GL.glVertex3f(x + d, 0, z + d)
                    GL.glVertex3f(x + d, 0, z)
            GL.glEnd()


def draw(w, h):
    GL.glViewport(0, 0, w, h)
    GL.glClearColor(0.55, 0.6, 0.7, 1)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glEnable(GL.GL_NORMALIZE)
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    a = w / h
    GL.glFrustum(-0.45 * a, 0.45 * a, -0.45, 0.45, 1.0, 25.0)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glTranslatef(0, -1.0, -6.5)
    GL.glRotatef(25, 1, 0, 0)
    GL.glRotatef(30, 0, 1, 0)

    GL.glLightModelfv(GL.GL_LIGHT_MODEL_AMBIENT, (0.1, 0.1, 0.1, 1))
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_POSITION, (0.5, 1.0, 0.8, 0.0))
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_DIFFUSE, (0.6, 0.6, 0.6, 1))
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_SPECULAR, (0.8, 0.8, 0.8, 1))
    # A spotlight from above, pointing down at the floor in front of the sphere.
    GL.glLightfv(GL.GL_LIGHT1, GL.GL_POSITION, (0.5, 4.0, 1.0, 1.0))
    GL.glLightfv(GL.GL_LIGHT1, GL.GL_SPOT_DIRECTION, (0.0, -1.0, 0.0))
    GL.glLightf(GL.GL_LIGHT1, GL.GL_SPOT_CUTOFF, 30.0)
    GL.glLightf(GL.GL_LIGHT1, GL.GL_SPOT_EXPONENT, 8.0)
    GL.glLightfv(GL.GL_LIGHT1, GL.GL_DIFFUSE, (0.9, 0.85, 0.5, 1))
    GL.glEnable(GL.GL_LIGHTING)
    GL.glEnable(GL.GL_LIGHT0)
    GL.glEnable(GL.GL_LIGHT1)

    GL.glFogi(GL.GL_FOG_MODE, GL.GL_LINEAR)
    GL.glFogf(GL.GL_FOG_START, 6.0)
    GL.glFogf(GL.GL_FOG_END, 14.0)
    GL.glFogfv(GL.GL_FOG_COLOR, (0.55, 0.6, 0.7, 1))
    GL.glEnable(GL.GL_FOG)

    GL.glMaterialfv(GL.GL_FRONT, GL.GL_SPECULAR, (0, 0, 0, 1))
    floor()

    # The sphere from client arrays: read by the library when glDrawArrays runs.
    vertices, normals, n = sphere_arrays(1.0, 36, 18)
    GL.glPushMatrix()
    GL.glTranslatef(-0.8, 1.0, 0.0)
    GL.glMaterialfv(GL.GL_FRONT, GL.GL_AMBIENT_AND_DIFFUSE, (0.2, 0.7, 0.3, 1))
    GL.glMaterialfv(GL.GL_FRONT, GL.GL_SPECULAR, (1, 1, 1, 1))
    GL.glMaterialf(GL.GL_FRONT, GL.GL_SHININESS, 40.0)
    GL.glEnableClientState(GL.GL_VERTEX_ARRAY)
    GL.glEnableClientState(GL.GL_NORMAL_ARRAY)
    GL.glVertexPointer(3, GL.GL_FLOAT, 0, vertices)
    GL.glNormalPointer(GL.GL_FLOAT, 0, normals)
    GL.glDrawArrays(GL.GL_TRIANGLES, 0, n)
    GL.glDisableClientState(GL.GL_VERTEX_ARRAY)
    GL.glDisableClientState(GL.GL_NORMAL_ARRAY)
    GL.glPopMatrix()

    GL.glPushMatrix()
    GL.glTranslatef(1.3, 0.8, 0.6)
    GL.glRotatef(20, 0, 1, 0)
    GL.glScalef(0.8, 0.8, 0.8)
    GL.glShadeModel(GL.GL_FLAT)
    GL.glMaterialfv(GL.GL_FRONT, GL.GL_AMBIENT_AND_DIFFUSE, (0.85, 0.35, 0.1, 1))
    GL.glMaterialf(GL.GL_FRONT, GL.GL_SHININESS, 10.0)
    octahedron()
    GL.glShadeModel(GL.GL_SMOOTH)
    GL.glPopMatrix()
    GL.glFinish()


def write(path, w, h, rows):
    """`rows`: top row first, RGB bytes each."""
    if path.endswith(".png"):
        raw = b"".join(b"\0" + r for r in rows)

        def chunk(kind, data):
            return (struct.pack(">I", len(data)) + kind + data
                    + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

        png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
               + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
        with open(path, "wb") as f:
            f.write(png)
    else:
        with open(path, "wb") as f:
            f.write(b"P6\n%d %d\n255\n" % (w, h))
            f.writelines(rows)


def main(argv):
    out, w, h = "pyopengl_demo.ppm", 320, 240
    args = iter(argv[1:])
    for a in args:
        if a == "--size":
            w, h = (int(v) for v in next(args).split("x"))
        else:
            out = a

    attribs = [osmesa.OSMESA_FORMAT, osmesa.OSMESA_RGBA, osmesa.OSMESA_DEPTH_BITS, 24,
               osmesa.OSMESA_STENCIL_BITS, 8, osmesa.OSMESA_PROFILE, 0x35,  # COMPAT_PROFILE
               0x36, 1, 0x37, 5,  # CONTEXT_MAJOR_VERSION 1, CONTEXT_MINOR_VERSION 5
               0]
    ctx = osmesa.OSMesaCreateContextAttribs(attribs, None)
    if not ctx:
        sys.exit("pyopengl_demo: OSMesaCreateContextAttribs failed")
    buf = (ctypes.c_ubyte * (w * h * 4))()
    if not osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, w, h):
        sys.exit("pyopengl_demo: OSMesaMakeCurrent failed")
    print("GL_RENDERER:", GL.glGetString(GL.GL_RENDERER).decode())

    draw(w, h)

    data = bytes(buf)
    # OSMesa's default (OSMESA_Y_UP): the buffer's first row is the bottom of the picture.
    rows = []
    for y in range(h - 1, -1, -1):
        line = data[4 * w * y: 4 * w * (y + 1)]
        rgb = bytearray(3 * w)
        rgb[0::3], rgb[1::3], rgb[2::3] = line[0::4], line[1::4], line[2::4]
        rows.append(bytes(rgb))
    write(out, w, h, rows)
    print("wrote %s (%dx%d)" % (out, w, h))
    osmesa.OSMesaDestroyContext(ctx)


if __name__ == "__main__":
    main(sys.argv)
