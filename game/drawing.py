"""Drawing a hole and the ball with batched shape lists, in world coordinates (metres).

Everything that does not move is built once per hole into one ShapeElementList (floor, hazards with
their textures, walls, the cup and its flag, the windmills' sweep); moving things (the ball, windmills)
are shape lists moved and turned each frame. Nothing here imports arcade.gui, so `polygolf render` can
draw in a headless (EGL) context.
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence

import arcade
from arcade.shape_list import (
    ShapeElementList,
    create_ellipse_filled,
    create_ellipse_outline,
    create_line,
    create_line_loop,
    create_line_strip,
    create_polygon,
    create_rectangle_filled,
)

from polygolf.engine.components.hazards import Region
from polygolf.engine.golf.layout import HoleLayout
from polygolf.engine.physics import polygon
from polygolf.engine.physics.settings import MAX_SHOT_SPIN
from polygolf.engine.physics.shot import clamp_arrow, shot_power
from polygolf.game.theme import RGBA, Theme

HUD_HEIGHT = 44  # pixels
MARGIN = 1.0  # metres of background around the hole
SHADOW = (0, 0, 0, 80)
SHADOW_OFFSET = (0.07, -0.09)  # metres: light from the top left
TEXTURE_SEED = 12  # sand speckles and ice streaks land in the same places every time


def shade(colour: RGBA, amount: float, alpha: int | None = None) -> RGBA:
    """`colour` mixed toward white (amount > 0) or black (amount < 0) by |amount|."""
    target = 255 if amount > 0 else 0
    mixed = tuple(round(c + (target - c) * abs(amount)) for c in colour[:3])
    return (*mixed, colour[3] if alpha is None else alpha)  # type: ignore[return-value]


def mix(a: RGBA, b: RGBA, t: float) -> RGBA:
    """The colour `t` of the way from `a` to `b` (opaque)."""
    return (*(round(x + (y - x) * t) for x, y in zip(a[:3], b[:3])), 255)  # type: ignore[return-value]


def _filled(shapes: ShapeElementList, outline: Sequence[polygon.Vec], fill, edge, edge_width: float) -> None:
    """A simple polygon, convex or not: filled piece by piece, then outlined once."""
    for piece in polygon.convex_pieces(tuple(outline)):
        shapes.append(create_polygon(list(piece), fill))
    if edge is not None:
        shapes.append(create_line_loop(list(outline), edge, edge_width))


def _region(outline: Sequence[polygon.Vec]) -> Region:
    xs, ys = zip(*outline)
    return Region(tuple(outline), (min(xs), min(ys), max(xs), max(ys)))


def _grid_points(region: Region, step: float, offset: float = 0.0):
    """Points of a world-aligned grid inside `region`: zones on neighbouring tiles continue one pattern."""
    x0, y0, x1, y1 = region.aabb
    x = math.floor(x0 / step) * step + step / 2 + offset
    while x < x1:
        y = math.floor(y0 / step) * step + step / 2
        while y < y1:
            if region.contains(x, y):
                yield x, y
            y += step
        x += step


def _edges_not_shared(outline: polygon.Outline, others: Sequence[polygon.Outline]) -> list[tuple[polygon.Vec, ...]]:
    """The edges of `outline` that no other zone of the same surface shares: the zone's outer rim,
    without seams between the tiles of one ice sheet or one slope."""

    def key(a: polygon.Vec, b: polygon.Vec) -> tuple:
        return tuple(sorted(((round(a[0], 3), round(a[1], 3)), (round(b[0], 3), round(b[1], 3)))))

    shared = set()
    for other in others:
        if other is not outline:
            shared |= {key(other[i], other[(i + 1) % len(other)]) for i in range(len(other))}
    edges = [(outline[i], outline[(i + 1) % len(outline)]) for i in range(len(outline))]
    return [edge for edge in edges if key(*edge) not in shared]


def _texture(shapes: ShapeElementList, kind: str, region: Region, colour: RGBA, push, rng: random.Random) -> None:
    """What makes a surface readable at a glance, beyond its colour."""
    if kind == "sand":  # speckled
        for x, y in _grid_points(region, 0.32):
            px, py = x + rng.uniform(-0.14, 0.14), y + rng.uniform(-0.14, 0.14)
            if region.contains(px, py):
                grain = shade(colour, rng.choice((-0.28, -0.18, 0.3)))
                size = rng.uniform(0.06, 0.11)
                shapes.append(create_ellipse_filled(px, py, size, size, grain, num_segments=6))
    elif kind == "water":  # ripples: short arcs in rows
        ripple = shade(colour, 0.35)
        for x, y in _grid_points(region, 1.1):
            arc = [(x + 0.32 * math.cos(a), y - 0.1 + 0.14 * math.sin(a)) for a in (0.5, 1.05, 1.57, 2.1, 2.65)]
            if all(region.contains(*p) for p in arc):
                shapes.append(create_line_strip(arc, ripple, 0.05))
    elif kind == "ice":  # a sheen: pale diagonal streaks
        # White glints on a tinted sheet; on a nearly white one, bluish-grey glints (white would vanish).
        streak = shade(colour, 0.75, alpha=200) if sum(colour[:3]) < 660 else (*shade(colour, -0.3)[:3], 220)
        for x, y in _grid_points(region, 1.4):
            length = rng.uniform(0.35, 0.7)
            a, b = (x - length / 2, y - length / 2), (x + length / 2, y + length / 2)
            if region.contains(*a) and region.contains(*b):
                shapes.append(create_line(*a, *b, streak, 0.06))
                c = (b[0] + 0.18, b[1] - 0.05)
                d = (c[0] + length / 3, c[1] + length / 3)
                if region.contains(*d):
                    shapes.append(create_line(*c, *d, streak, 0.04))
    elif kind == "slope":  # chevrons pointing downhill
        length = math.hypot(*push) or 1.0
        ux, uy = push[0] / length, push[1] / length
        size = 0.28
        for x, y in _grid_points(region, 1.2):
            tip = (x + ux * size, y + uy * size)
            left = (x - ux * size - uy * size, y - uy * size + ux * size)
            right = (x - ux * size + uy * size, y - uy * size - ux * size)
            shapes.append(create_line_strip([left, tip, right], colour, 0.09))


ZONE_COLOURS = {"sand": "sand_zone", "water": "water", "ice": "ice", "slope": "slope"}
SLOPE_TINT = 0.5  # a slope's floor: the green this far toward the slope colour, under chevrons in that colour


class HoleArt:
    """The static picture of a hole, one batched draw call; windmills are drawn moving on top."""

    def __init__(self, layout: HoleLayout, theme: Theme, ball_radius: float = 0.5,
                 tees: Sequence[tuple[float, float]] = ()) -> None:
        shapes: ShapeElementList = ShapeElementList()
        rng = random.Random(TEXTURE_SEED)
        size = layout.tile_size
        for x0, y0, x1, y1 in layout.floor:
            colour = theme.rgba("green_alt" if (round(x0 / size) + round(y0 / size)) % 2 else "green")
            shapes.append(create_rectangle_filled((x0 + x1) / 2, (y0 + y1) / 2, x1 - x0 + 0.02, y1 - y0 + 0.02, colour))
        # The tee: a mat every ball on it (each player's spot, `tees`; even a star's tips) sits inside.
        xs, ys = zip(*(tees or [layout.tee]))
        half = ball_radius + 0.15
        left, right, bottom, top = min(xs) - half, max(xs) + half, min(ys) - half, max(ys) + half
        tx, ty, wide, high = (left + right) / 2, (bottom + top) / 2, right - left, top - bottom
        shapes.append(create_rectangle_filled(tx, ty, wide + 0.1, high + 0.1, theme.rgba("tee")))
        shapes.append(create_rectangle_filled(tx, ty, wide, high, theme.rgba("green")))
        zones = sorted(layout.zones, key=lambda z: z[0] == "slope")
        for kind, outline, push in zones:
            colour = theme.rgba(ZONE_COLOURS[kind])
            fill = mix(theme.rgba("green"), colour, SLOPE_TINT) if kind == "slope" else colour
            _filled(shapes, outline, fill, None, 0.0)
            _texture(shapes, kind, _region(outline), colour, push, rng)
            same = [o for k, o, _ in layout.zones if k == kind]
            rim = shade(colour, -0.35) if kind != "slope" else colour
            for a, b in _edges_not_shared(outline, same):
                shapes.append(create_line(*a, *b, rim, 0.06))
        # The windmills' sweep: where a blade will pass.
        for local, (px, py), _ in layout.windmills:
            reach = 2 * polygon.bounding_radius(local)
            shapes.append(create_ellipse_outline(px, py, reach, reach, shade(theme.rgba("windmill"), 0.0, 110), 0.05,
                                                 num_segments=64))
            shapes.append(create_ellipse_filled(px, py, reach, reach, shade(theme.rgba("windmill"), 0.0, 28),
                                                num_segments=64))
        cx, cy = layout.cup
        cup_r = layout.cup_radius
        rim = 2 * cup_r + 0.12
        shapes.append(create_ellipse_filled(cx, cy, rim, rim, theme.rgba("cup_rim"), num_segments=48))
        shapes.append(create_ellipse_filled(cx, cy, 2 * cup_r, 2 * cup_r, theme.rgba("cup"), num_segments=48))
        for outline in layout.borders:
            _filled(shapes, outline, theme.rgba("wall"), theme.rgba("wall_edge"), 0.06)
        for outline, _ in layout.obstacles:
            _filled(shapes, outline, theme.rgba("obstacle"), theme.rgba("obstacle_edge"), 0.06)
        for outline, _, _ in layout.bumpers:  # ringed: a bright band inside a dark rim
            _filled(shapes, outline, theme.rgba("bumper"), shade(theme.rgba("bumper"), -0.55), 0.14)
            inner = _inset(outline, 0.12)
            if inner is not None:
                shapes.append(create_line_loop(inner, shade(theme.rgba("bumper"), 0.6), 0.06))
        self.shapes = shapes
        self.flag = FlagArt(layout.cup, cup_r, theme)
        self.bumper_outlines = [outline for outline, _, _ in layout.bumpers]
        self.windmills = [PolygonArt(outline, theme, fill="windmill", edge="obstacle_edge", marker=False)
                          for outline, _, _ in layout.windmills]
        self.cup = layout.cup
        self.cup_radius = cup_r

    def draw(self, lit_bumpers: Sequence[bool] = (), windmill_poses: Sequence[tuple[float, float, float]] = (),
             theme: Theme | None = None) -> None:
        self.shapes.draw()
        for outline, lit in zip(self.bumper_outlines, lit_bumpers):
            if lit and theme is not None:
                arcade.draw_polygon_outline(list(outline), theme.rgba("bumper_lit"), 0.14)
        for art, pose in zip(self.windmills, windmill_poses):
            art.draw(*pose)

    def draw_flag(self) -> None:
        self.flag.shapes.draw()


def _inset(outline: polygon.Outline, by: float) -> list[polygon.Vec] | None:
    """The outline pulled toward its centroid by `by` metres (about its size), or None if too small."""
    cx = sum(x for x, _ in outline) / len(outline)
    cy = sum(y for _, y in outline) / len(outline)
    reach = max(math.hypot(x - cx, y - cy) for x, y in outline)
    if reach <= 2 * by:
        return None
    k = (reach - by) / reach
    return [(cx + (x - cx) * k, cy + (y - cy) * k) for x, y in outline]


class FlagArt:
    """The pin: a pole from the cup's rim and a pennant, so the target reads from across the hole."""

    def __init__(self, cup: polygon.Vec, cup_radius: float, theme: Theme) -> None:
        x, y = cup[0] + cup_radius * 0.7, cup[1] + cup_radius * 0.7
        top = y + 1.6
        self.shapes: ShapeElementList = ShapeElementList()
        self.shapes.append(create_line(x + 0.05, y - 0.05, x + 0.05, top - 0.05, SHADOW, 0.07))
        self.shapes.append(create_line(x, y, x, top, theme.rgba("cup_rim"), 0.07))
        self.shapes.append(create_polygon([(x, top), (x, top - 0.55), (x + 0.85, top - 0.3)], theme.rgba("flag")))
        self.shapes.append(create_line_loop([(x, top), (x, top - 0.55), (x + 0.85, top - 0.3)],
                                            shade(theme.rgba("flag"), -0.5), 0.03))


class PolygonArt:
    """A moving polygon (the ball, a windmill), built once in its own frame and moved and turned each
    frame; the ball also gets a shadow and a marker that shows its spin."""

    def __init__(self, outline: Sequence[polygon.Vec], theme: Theme, scale: float = 1.0, fill: str = "ball",
                 edge: str = "ball_edge", marker: bool = True, colour: RGBA | None = None) -> None:
        local = [(x * scale, y * scale) for x, y in outline]
        self.outline = local
        self.fill, self.edge = colour or theme.rgba(fill), theme.rgba(edge)
        self.shapes: ShapeElementList = ShapeElementList()
        _filled(self.shapes, local, self.fill, self.edge, 0.05 * max(scale, 1.0))
        if marker:
            # A dot toward the first vertex, inside even a thin star: it shows the spin on any shape.
            inner = min(math.hypot(x, y) for x, y in local)
            x, y = local[0]
            reach = math.hypot(x, y) or 1.0
            dot = 0.55 * inner
            dx, dy = x / reach * 0.5 * inner, y / reach * 0.5 * inner
            self.shapes.append(create_ellipse_filled(dx, dy, dot, dot, self.edge, num_segments=20))
            self.shapes.append(create_ellipse_filled(dx, dy, 0.45 * dot, 0.45 * dot, shade(self.fill, 0.7),
                                                     num_segments=16))
        self.shadow: ShapeElementList = ShapeElementList()
        _filled(self.shadow, local, SHADOW, None, 0.0)

    def draw(self, x: float, y: float, angle: float, shadow: bool = False) -> None:
        lists = (self.shadow, self.shapes) if shadow else (self.shapes,)
        for shapes, (ox, oy) in zip(lists, (SHADOW_OFFSET, (0.0, 0.0)) if shadow else ((0.0, 0.0),)):
            shapes.position = (x + ox, y + oy)
            shapes.angle = -math.degrees(angle)  # shape lists turn clockwise
            shapes.draw()

    def draw_scaled(self, x: float, y: float, angle: float, scale: float) -> None:
        """Immediate-mode, for the short moment the ball shrinks into the cup."""
        c, s = math.cos(angle) * scale, math.sin(angle) * scale
        points = [(x + c * px - s * py, y + s * px + c * py) for px, py in self.outline]
        arcade.draw_polygon_filled(points, self.fill)
        arcade.draw_polygon_outline(points, self.edge, 0.04)



def draw_trail(points: Sequence[polygon.Vec], colour: RGBA, width: float) -> None:
    """The ball's recent path, fading toward its oldest point."""
    count = len(points)
    for i in range(1, count):
        alpha = round(150 * i / count)
        arcade.draw_line(*points[i - 1], *points[i], (*colour[:3], alpha), width * i / count)


def power_colour(theme: Theme, fraction: float) -> RGBA:
    """The arrow's colour at `fraction` of full power: the theme's ramp from `arrow` to `arrow_strong`,
    chosen light to dark (or blue to orange) so it reads without red-green vision."""
    weak, strong = theme.rgba("arrow"), theme.rgba("arrow_strong")
    return tuple(round(a + (b - a) * fraction) for a, b in zip(weak, strong))  # type: ignore[return-value]


def draw_arrow(origin: polygon.Vec, tip: polygon.Vec, theme: Theme, centre: polygon.Vec | None = None,
               spin: float = 0.0, ball_radius: float = 0.5, alpha: int = 255) -> float:
    """The aiming arrow from where the ball was grabbed to the pointer: longer, wider and darker with
    power; around the ball, an arc whose length and direction show the spin the grab point gives.
    `alpha` < 255 draws it faintly (the aim hint). Returns the power fraction (1.0 = the strongest shot)."""
    arrow = (tip[0] - origin[0], tip[1] - origin[1])
    length = math.hypot(*arrow)
    if length < 1e-6:
        return 0.0
    fraction = shot_power(arrow)
    ux, uy = arrow[0] / length, arrow[1] / length
    shown = clamp_arrow(arrow) or arrow
    end = (origin[0] + shown[0], origin[1] + shown[1])
    colour = power_colour(theme, fraction)
    outline = shade(colour, -0.6) if sum(colour[:3]) > 380 else shade(colour, 0.6)
    colour, outline = (*colour[:3], alpha), (*outline[:3], alpha)
    width = 0.08 + 0.16 * fraction
    head = 0.35 + 0.25 * fraction
    base = (end[0] - ux * head * 0.8, end[1] - uy * head * 0.8)  # the shaft stops inside the head
    arcade.draw_line(origin[0], origin[1], base[0], base[1], outline, width + 0.06)
    arcade.draw_line(origin[0], origin[1], base[0], base[1], colour, width)
    left = (end[0] - ux * head - uy * head * 0.6, end[1] - uy * head + ux * head * 0.6)
    right = (end[0] - ux * head + uy * head * 0.6, end[1] - uy * head - ux * head * 0.6)
    arcade.draw_polygon_filled([end, left, right], colour)
    arcade.draw_polygon_outline([end, left, right], outline, 0.03)
    if centre is not None and abs(spin) > 0.05 * MAX_SHOT_SPIN:
        draw_spin(centre, spin, ball_radius, colour, outline)
    return fraction


def dotted_path(points: Sequence[polygon.Vec], theme: Theme, contact: polygon.Vec | None = None,
                spacing: float = 0.35, size: float = 0.07) -> ShapeElementList:
    """The shot preview, built once per path (one batched draw a frame): dots every `spacing` m along
    `points` in the arrow's light colour, each ringed in a dark one so they read on any surface, and
    a ring on the point where the ball first strikes something."""
    light = theme.rgba("arrow")
    dark = shade(light, -0.7) if sum(light[:3]) > 380 else shade(light, 0.7)
    shapes: ShapeElementList = ShapeElementList()
    ahead = spacing  # distance along the path to the next dot (none on the ball's centre)
    for (ax, ay), (bx, by) in zip(points, points[1:]):
        length = math.hypot(bx - ax, by - ay)
        while ahead <= length:
            x, y = ax + (bx - ax) * ahead / length, ay + (by - ay) * ahead / length
            shapes.append(create_ellipse_filled(x, y, 2 * size + 0.07, 2 * size + 0.07, (*dark[:3], 210),
                                                num_segments=10))
            shapes.append(create_ellipse_filled(x, y, 2 * size, 2 * size, (*light[:3], 235), num_segments=10))
            ahead += spacing
        ahead -= length
    if contact is not None:
        x, y = contact
        ring = 0.5
        shapes.append(create_ellipse_outline(x, y, ring, ring, (*dark[:3], 170), 0.1, num_segments=32))
        shapes.append(create_ellipse_outline(x, y, ring, ring, (*light[:3], 230), 0.05, num_segments=32))
    return shapes


def draw_spin(centre: polygon.Vec, spin: float, ball_radius: float, colour: RGBA, outline: RGBA) -> None:
    """An arc around the ball, up to 300° at the strongest spin, with a head in the spin's direction."""
    sweep = 300.0 * min(1.0, abs(spin) / MAX_SHOT_SPIN)
    radius = ball_radius + 0.25
    start = 90.0
    end = start + sweep if spin > 0 else start - sweep
    low, high = min(start, end), max(start, end)
    arcade.draw_arc_outline(centre[0], centre[1], 2 * radius, 2 * radius, outline, low, high, 0.16, num_segments=64)
    arcade.draw_arc_outline(centre[0], centre[1], 2 * radius, 2 * radius, colour, low, high, 0.1, num_segments=64)
    a = math.radians(end)
    px, py = centre[0] + radius * math.cos(a), centre[1] + radius * math.sin(a)
    tx, ty = -math.sin(a) * (1 if spin > 0 else -1), math.cos(a) * (1 if spin > 0 else -1)  # along the turn
    nx, ny = math.cos(a), math.sin(a)
    head = [(px + tx * 0.42, py + ty * 0.42), (px - tx * 0.06 + nx * 0.14, py - ty * 0.06 + ny * 0.14),
            (px - tx * 0.06 - nx * 0.14, py - ty * 0.06 - ny * 0.14)]
    arcade.draw_polygon_filled(head, colour)
    arcade.draw_polygon_outline(head, outline, 0.03)


def fit_zoom(bounds: tuple[float, float, float, float], width: float, height: float) -> float:
    """Pixels per metre that fit the hole, with its margin, in a `width` x `height` area."""
    x0, y0, x1, y1 = bounds
    return min(width / (x1 - x0 + 2 * MARGIN), max(1.0, height) / (y1 - y0 + 2 * MARGIN))


def fit_camera(camera: arcade.Camera2D, bounds: tuple[float, float, float, float], width: int, height: int,
               hud: int = HUD_HEIGHT, left: int = 0, zoom: float = 1.0,
               pan: tuple[float, float] = (0.0, 0.0)) -> None:
    """Zoom and centre the camera so the hole fills the window below the HUD bar and right of a `left`
    panel; `zoom` (x the fit) and `pan` (metres) are the player's own view on top."""
    x0, y0, x1, y1 = bounds
    fitted = fit_zoom(bounds, width - left, height - hud)
    camera.match_window()
    camera.zoom = fitted * zoom
    # Centre the hole in the area under the HUD and right of the panel.
    camera.position = ((x0 + x1) / 2 - left / 2 / camera.zoom + pan[0],
                       (y0 + y1) / 2 + hud / 2 / camera.zoom + pan[1])


# Seats 2 to 4 take the first of these that is not too like the theme's ball (seat 1's colour) or an
# earlier seat's: Sand's blue ball would otherwise share seat 2's blue, Night's pink one seat 3's red.
# And, while there are enough, one lighter or darker than both of the green's shades: a red ball as
# light as Grass's green (1.04 : 1) is told from it by hue alone, which a red-green blind player lacks.
SEAT_COLOURS: tuple[RGBA, ...] = ((79, 195, 247, 255), (239, 83, 80, 255), (186, 104, 200, 255),
                                  (255, 167, 38, 255), (245, 245, 245, 255), (26, 35, 126, 255), (183, 28, 28, 255))
SEAT_DISTANCE = 70.0  # RGB distance under which two balls are taken for one (as tests/test_theme_colours)
SEAT_CONTRAST = 1.5  # lightness contrast (WCAG's ratio) a seat's ball keeps from both greens, where it can


def lightness(rgb: Sequence[int]) -> float:
    """WCAG relative luminance, 0 (black) to 1 (white)."""
    def linear(c: int) -> float:
        c /= 255
        return c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4

    r, g, b = (linear(c) for c in rgb[:3])
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def contrast(a: Sequence[int], b: Sequence[int]) -> float:
    """WCAG's contrast ratio of two colours' lightness, 1 (the same) to 21 (black on white)."""
    light, dark = sorted((lightness(a), lightness(b)), reverse=True)
    return (light + 0.05) / (dark + 0.05)


def player_colour(theme: Theme, seat: int) -> RGBA:
    """The colour of seat `seat`'s ball (0-based): seat 0 the theme's ball, the others each a colour
    of their own, far enough from the ball's and from each other's to tell apart, and lighter or
    darker than the green where four such colours can be found."""
    greens = (theme.rgba("green"), theme.rgba("green_alt"))
    taken = [theme.rgba("ball")]
    for light_enough in (True, False):
        for colour in SEAT_COLOURS:
            if len(taken) > seat:
                return taken[seat]
            if colour not in taken and all(math.dist(colour[:3], other[:3]) >= SEAT_DISTANCE for other in taken) \
                    and (not light_enough or min(contrast(colour, green) for green in greens) >= SEAT_CONTRAST):
                taken.append(colour)
    return taken[seat] if seat < len(taken) else SEAT_COLOURS[seat % len(SEAT_COLOURS)]


class PlayerBallArt(PolygonArt):
    """A player's ball: seat 1 in the theme's ball colour, the others in their own colour, so everyone
    on the green can tell whose ball is whose."""

    def __init__(self, outline: Sequence[polygon.Vec], theme: Theme, seat: int) -> None:
        super().__init__(outline, theme, colour=player_colour(theme, seat))

    @property
    def colour(self) -> RGBA:
        return self.fill


def draw_turn_ring(x: float, y: float, radius: float, colour) -> None:
    """A ring around the ball whose turn it is."""
    arcade.draw_circle_outline(x, y, radius * 1.45, colour, 0.07, num_segments=40)


def fit_width(text: arcade.Text, full: str, width: float, size: float, smallest: float = 9.0,
              middle: bool = False) -> None:
    """Show `full` in `text` at most `width` pixels wide: at `size`, else as much smaller as it needs
    (down to `smallest`), else at `smallest` cut short with an ellipsis (in the `middle`, for a name:
    `cut_middle`). A long player name or a narrow window then never runs text into its neighbours.
    The cut is found by halving (a layout a try): text longer than any window shows (QA: a label of
    100 000 characters edited into the settings) is first cut to what could fit at all, some two
    pixels a character at the smallest size."""
    most = int(width / 2.0) + 2
    if len(full) > most:
        full = cut_middle(full, most) if middle else full[:most]
    text.text, text.font_size = full, size
    if text.content_width <= width:
        return
    for _ in range(3):  # widths scale almost linearly with the size; a pass or two settles rounding
        text.font_size = max(smallest, text.font_size * width / max(text.content_width, 1.0))
        if text.content_width <= width or text.font_size <= smallest:
            break
    while text.content_width > width and text.font_size > smallest:  # glyphs come in whole pixel sizes:
        text.font_size = max(smallest, text.font_size - 0.5)  # a width can stay put as the size falls a little
    if text.content_width <= width:
        return
    def cut(keep: int) -> str:
        return cut_middle(full, keep) if middle else full[:keep].rstrip() + "…"

    fits, wide = 1, len(full)  # the most characters kept that fit, and the fewest that do not
    while wide - fits > 1:
        keep = (fits + wide) // 2
        text.text = cut(keep)
        if text.content_width <= width:
            fits = keep
        else:
            wide = keep
    text.text = cut(fits)


def cut_middle(name: str, keep: int) -> str:
    """`name` if at most `keep` characters long, else `keep` of them about an ellipsis in the middle
    ('Wilhelmi…rth'): names that differ only at the end ('Ann', 'Ann 2') stay apart."""
    if len(name) <= keep:
        return name
    tail = max(1, keep // 3)
    return name[:keep - tail].rstrip() + "…" + name[len(name) - tail:].lstrip()


def text_box(text: arcade.Text) -> tuple[float, float, float, float]:
    """(left, bottom, right, top) of what `text` shows on the screen, whatever its anchors, and
    inside a wider wrapping width as its alignment puts it."""
    left, right = text.left, text.right
    spare = (right - left) - text.content_width
    left += {"left": 0.0, "center": spare / 2, "right": spare}.get(text.align, 0.0) if text.multiline else 0.0
    return left, text.bottom, left + text.content_width, text.bottom + text.content_height


def draw_backed(text: arcade.Text, backing: RGBA, pad: float = 12.0) -> None:
    """`text` on a `backing` panel `pad` pixels wider each side (half that above and below), so it
    reads over anything: a hole, or a background its colour is too close to."""
    if not text.text:
        return
    left, bottom, right, top = text_box(text)
    arcade.draw_lrbt_rectangle_filled(left - pad, right + pad, bottom - pad / 2, top + pad / 2, backing)
    text.draw()
