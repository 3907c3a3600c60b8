#!/usr/bin/env python3
"""Renders a terminal capture with ANSI colours (`tmux capture-pane -e -p`) to a PNG.

Usage: render_terminal.py CAPTURE.txt OUT.png [COLUMNS ROWS]
Understands the SGR codes tmux writes: reset, bold, italic, underline, reverse, the 16
colours, 256 colours and 24-bit colours, default foreground and background. Draws with
DejaVu Sans Mono (Debian's fonts-dejavu-core) and Python's PIL (python3-pil).
"""
import re
import sys

from PIL import Image, ImageDraw, ImageFont

FONT_DIR = "/usr/share/fonts/truetype/dejavu/"
FONT_SIZE = 16
BACKGROUND = (30, 30, 36)
FOREGROUND = (220, 220, 214)
# The 16 base colours (xterm's defaults, a little softened).
BASE = [(0, 0, 0), (205, 49, 49), (13, 188, 121), (229, 229, 16), (36, 114, 200),
        (188, 63, 188), (17, 168, 205), (229, 229, 229), (102, 102, 102), (241, 76, 76),
        (35, 209, 139), (245, 245, 67), (59, 142, 234), (214, 112, 214), (41, 184, 219),
        (255, 255, 255)]
SGR = re.compile(r"\x1b\[([0-9;:]*)m")


def colour256(n):
    if n < 16:
        return BASE[n]
    if n < 232:
        n -= 16
        steps = [0, 95, 135, 175, 215, 255]
        return steps[n // 36], steps[(n // 6) % 6], steps[n % 6]
    level = 8 + (n - 232) * 10
    return level, level, level


class Style:
    def __init__(self):
        self.reset()

    def reset(self):
        self.fg, self.bg = None, None
        self.bold = self.italic = self.underline = self.reverse = False

    def apply(self, codes):
        codes = [int(c) if c else 0 for c in re.split("[;:]", codes)] or [0]
        i = 0
        while i < len(codes):
            c = codes[i]
            if c == 0:
                self.reset()
            elif c in (1, 3, 4, 7):
                setattr(self, {1: "bold", 3: "italic", 4: "underline", 7: "reverse"}[c], True)
            elif c in (22, 23, 24, 27):
                setattr(self, {22: "bold", 23: "italic", 24: "underline", 27: "reverse"}[c],
                        False)
            elif 30 <= c <= 37 or 90 <= c <= 97:
                self.fg = BASE[c - 30 if c < 90 else c - 82]
            elif 40 <= c <= 47 or 100 <= c <= 107:
                self.bg = BASE[c - 40 if c < 100 else c - 92]
            elif c == 39:
                self.fg = None
            elif c == 49:
                self.bg = None
            elif c in (38, 48) and i + 1 < len(codes):
                if codes[i + 1] == 5 and i + 2 < len(codes):
                    colour, i = colour256(codes[i + 2]), i + 2
                elif codes[i + 1] == 2 and i + 4 < len(codes):
                    colour, i = tuple(codes[i + 2:i + 5]), i + 4
                else:
                    colour = None
                setattr(self, "fg" if c == 38 else "bg", colour)
            i += 1

    def colours(self):
        fg, bg = self.fg or FOREGROUND, self.bg or BACKGROUND
        return (bg, fg) if self.reverse else (fg, bg)


def cells(line, style):
    """Yields (character, fg, bg, bold, italic, underline) for each cell of `line`."""
    pos = 0
    for match in SGR.finditer(line):
        for ch in line[pos:match.start()]:
            yield (ch, *style.colours(), style.bold, style.italic, style.underline)
        style.apply(match.group(1))
        pos = match.end()
    for ch in line[pos:]:
        yield (ch, *style.colours(), style.bold, style.italic, style.underline)


def render(text, columns, rows):
    fonts = {(b, i): ImageFont.truetype(FONT_DIR + name, FONT_SIZE) for (b, i), name in {
        (False, False): "DejaVuSansMono.ttf", (True, False): "DejaVuSansMono-Bold.ttf",
        (False, True): "DejaVuSansMono-Oblique.ttf",
        (True, True): "DejaVuSansMono-BoldOblique.ttf"}.items()}
    width = round(fonts[False, False].getlength("M"))
    height = round(FONT_SIZE * 1.3)
    image = Image.new("RGB", (columns * width + 16, rows * height + 16), BACKGROUND)
    draw = ImageDraw.Draw(image)
    style = Style()
    for row, line in enumerate(text.split("\n")[:rows]):
        for column, (ch, fg, bg, bold, italic, underline) in enumerate(cells(line, style)):
            x, y = 8 + column * width, 8 + row * height
            draw.rectangle([x, y, x + width, y + height], fill=bg)
            draw.text((x, y + 2), ch, font=fonts[bold, italic], fill=fg)
            if underline:
                draw.line([x, y + height - 2, x + width, y + height - 2], fill=fg)
    return image


def main():
    capture, out = sys.argv[1], sys.argv[2]
    with open(capture, encoding="utf-8", errors="replace") as f:
        text = f.read().rstrip("\n")
    lines = [SGR.sub("", line) for line in text.split("\n")]
    columns = int(sys.argv[3]) if len(sys.argv) > 3 else max(len(line) for line in lines)
    rows = int(sys.argv[4]) if len(sys.argv) > 4 else len(lines)
    render(text, columns, rows).save(out)


if __name__ == "__main__":
    main()
