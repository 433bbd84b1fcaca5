"""PFM images as the bench scripts compare them (light-choice-error.sh, spectral-error.sh)."""
import math
import struct


def read_region(path, x0=0.0, y0=0.0, x1=1.0, y1=1.0):
    """The linear RGB values of a PFM image's region, as fractions of its width and height from
    the top left, flattened row by row."""
    with open(path, 'rb') as f:
        assert f.readline().strip() == b'PF'
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        fmt = '<' if scale < 0 else '>'
        values = struct.unpack(fmt + 'f' * (3 * w * h), f.read(12 * w * h))
    picked = []
    for row in range(h):  # PFM rows run bottom to top; the region counts from the top
        top = h - 1 - row
        if not (y0 * h <= top < y1 * h):
            continue
        for x in range(int(x0 * w), int(x1 * w)):
            picked.extend(values[3 * (row * w + x):3 * (row * w + x) + 3])
    return picked


def rmse(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / len(a))
