#!/usr/bin/env python3
"""Checks an xwd screenshot of the play window: not blank, and the HUD drawn (its dark band at the
top holds white text, and differs from the scene right below it). Standard library only."""
import struct
import sys

HUD_BAND_PX = 13  # src/play/hud.hpp, kHudBandPx


def read_xwd(path):
    data = open(path, "rb").read()
    fields = struct.unpack(">25I", data[:100])
    header_size, width, height = fields[0], fields[4], fields[5]
    bits_per_pixel, bytes_per_line, byte_order = fields[11], fields[12], fields[7]
    masks = fields[14:17]
    ncolors = fields[19]
    if bits_per_pixel != 32:
        raise SystemExit(f"check_screenshot: {bits_per_pixel} bits per pixel, expected 32")
    start = header_size + 12 * ncolors
    order = "<" if byte_order == 0 else ">"

    def shift(mask):
        return (mask & -mask).bit_length() - 1

    shifts = [shift(m) for m in masks]
    rows = []
    for y in range(height):
        line = data[start + y * bytes_per_line: start + y * bytes_per_line + 4 * width]
        px = struct.unpack(f"{order}{width}I", line)
        rows.append([tuple((p & m) >> s for m, s in zip(masks, shifts)) for p in px])
    return width, height, rows


def main():
    width, height, rows = read_xwd(sys.argv[1])
    if (width, height) != (640, 360):
        raise SystemExit(f"check_screenshot: window is {width}x{height}, expected 640x360")
    colours = {c for row in rows for c in row}
    if len(colours) < 20:
        raise SystemExit(f"check_screenshot: {len(colours)} colours: blank")
    band = [c for row in rows[:HUD_BAND_PX] for c in row]
    # White text, or amber when the HUD says simulated time is slowed (hud.hpp).
    white = sum(1 for c in band if c in ((255, 255, 255), (255, 200, 0)))
    black = sum(1 for c in band if c == (0, 0, 0))
    if white < 100 or white + black != len(band):
        raise SystemExit(f"check_screenshot: HUD band has {white} text and {black} band pixels "
                         f"of {len(band)}")
    below = rows[HUD_BAND_PX + 2]
    if sum(1 for c in below if c == (0, 0, 0)) > width // 2:
        raise SystemExit("check_screenshot: the picture below the HUD is as dark as its band")
    print(f"check_screenshot: {len(colours)} colours, HUD text {white} pixels")


main()
