"""Drawing a hole and the ball with batched shape lists, in world coordinates (metres).

Nothing here imports arcade.gui, so `polygolf render` can draw in a headless (EGL) context.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import arcade
from arcade.shape_list import (
    ShapeElementList,
    create_ellipse_filled,
    create_line_loop,
    create_line_strip,
    create_polygon,
    create_rectangle_filled,
)

from polygolf.engine.golf.layout import HoleLayout
from polygolf.engine.physics import polygon
from polygolf.engine.physics.shot import clamp_arrow, shot_power
from polygolf.game.theme import Theme

HUD_HEIGHT = 44  # pixels
MARGIN = 1.0  # metres of background around the hole


def _filled(shapes: ShapeElementList, outline: Sequence[polygon.Vec], fill, edge, edge_width: float) -> None:
    """A simple polygon, convex or not: filled piece by piece, then outlined once."""
    for piece in polygon.convex_pieces(tuple(outline)):
        shapes.append(create_polygon(list(piece), fill))
    shapes.append(create_line_loop(list(outline), edge, edge_width))


class HoleArt:
    """The static picture of a hole: floor, walls, obstacles, tee and cup, one batched draw call."""

    def __init__(self, layout: HoleLayout, theme: Theme) -> None:
        shapes: ShapeElementList = ShapeElementList()
        size = layout.tile_size
        for x0, y0, x1, y1 in layout.floor:
            colour = theme.rgba("green_alt" if (round(x0 / size) + round(y0 / size)) % 2 else "green")
            shapes.append(create_rectangle_filled((x0 + x1) / 2, (y0 + y1) / 2, x1 - x0 + 0.02, y1 - y0 + 0.02, colour))
        tx, ty = layout.tee
        shapes.append(create_rectangle_filled(tx, ty, 0.9, 0.9, theme.rgba("tee")))
        shapes.append(create_rectangle_filled(tx, ty, 0.8, 0.8, theme.rgba("green")))
        zone_colour = {"sand": "sand_zone", "water": "water", "ice": "ice", "slope": "slope"}
        for kind, outline, push in sorted(layout.zones, key=lambda z: z[0] == "slope"):
            colour = theme.rgba(zone_colour[kind])
            if kind == "slope":
                _slope_arrows(shapes, outline, push, colour)
            else:
                edge = tuple(max(0, c - 40) for c in colour[:3]) + (255,)
                _filled(shapes, outline, colour, edge, 0.05)
        cx, cy = layout.cup
        cup_r = layout.cup_radius
        rim = 2 * cup_r + 0.12
        shapes.append(create_ellipse_filled(cx, cy, rim, rim, theme.rgba("cup_rim"), num_segments=48))
        shapes.append(create_ellipse_filled(cx, cy, 2 * cup_r, 2 * cup_r, theme.rgba("cup"), num_segments=48))
        for outline in layout.borders:
            _filled(shapes, outline, theme.rgba("wall"), theme.rgba("wall_edge"), 0.06)
        for outline, _ in layout.obstacles:
            _filled(shapes, outline, theme.rgba("obstacle"), theme.rgba("obstacle_edge"), 0.06)
        for outline, _, _ in layout.bumpers:
            _filled(shapes, outline, theme.rgba("bumper"), theme.rgba("obstacle_edge"), 0.06)
        self.shapes = shapes
        self.bumper_outlines = [outline for outline, _, _ in layout.bumpers]
        self.windmills = [BallArt(outline, theme, fill="windmill", edge="obstacle_edge")
                          for outline, _, _ in layout.windmills]
        self.cup_radius = cup_r

    def draw(self, lit_bumpers: Sequence[bool] = (), windmill_poses: Sequence[tuple[float, float, float]] = (),
             theme: Theme | None = None) -> None:
        self.shapes.draw()
        for outline, lit in zip(self.bumper_outlines, lit_bumpers):
            if lit and theme is not None:
                arcade.draw_polygon_outline(list(outline), theme.rgba("bumper_lit"), 0.14)
        for art, pose in zip(self.windmills, windmill_poses):
            art.draw(*pose)


def _slope_arrows(shapes: ShapeElementList, outline, push, colour) -> None:
    """A slope: a tint and a field of chevrons pointing downhill."""
    from polygolf.engine.components.hazards import Region

    xs, ys = zip(*outline)
    region = Region(tuple(outline), (min(xs), min(ys), max(xs), max(ys)))
    tint = (*colour[:3], 90)
    for piece in polygon.convex_pieces(tuple(outline)):
        shapes.append(create_polygon(list(piece), tint))
    length = math.hypot(*push) or 1.0
    ux, uy = push[0] / length, push[1] / length
    size = 0.28
    step = 1.2
    x = min(xs) + step / 2
    while x < max(xs):
        y = min(ys) + step / 2
        while y < max(ys):
            if region.contains(x, y):
                tip = (x + ux * size, y + uy * size)
                left = (x - ux * size - uy * size, y - uy * size + ux * size)
                right = (x - ux * size + uy * size, y - uy * size - ux * size)
                shapes.append(create_line_strip([left, tip, right], colour, 0.08))
            y += step
        x += step


class BallArt:
    """A moving polygon (the ball, a windmill), built once in its own frame and moved and turned each
    frame."""

    def __init__(self, outline: Sequence[polygon.Vec], theme: Theme, scale: float = 1.0, fill: str = "ball",
                 edge: str = "ball_edge") -> None:
        local = [(x * scale, y * scale) for x, y in outline]
        self.shapes: ShapeElementList = ShapeElementList()
        _filled(self.shapes, local, theme.rgba(fill), theme.rgba(edge), 0.05 * max(scale, 1.0))
        # A dot near the first vertex, so spin shows even on round-ish shapes.
        x, y = local[0]
        dot = 0.14 * polygon.bounding_radius(local)
        self.shapes.append(create_ellipse_filled(0.62 * x, 0.62 * y, dot, dot, theme.rgba("ball_edge")))

    def draw(self, x: float, y: float, angle: float) -> None:
        self.shapes.position = (x, y)
        self.shapes.angle = -math.degrees(angle)  # shape lists turn clockwise
        self.shapes.draw()


def draw_arrow(origin: polygon.Vec, tip: polygon.Vec, theme: Theme) -> float:
    """The aiming arrow from where the ball was grabbed to the pointer, coloured by power.
    Returns the power fraction (1.0 = the strongest shot)."""
    arrow = (tip[0] - origin[0], tip[1] - origin[1])
    length = math.hypot(*arrow)
    if length < 1e-6:
        return 0.0
    fraction = shot_power(arrow)
    ux, uy = arrow[0] / length, arrow[1] / length
    shown = clamp_arrow(arrow) or arrow
    end = (origin[0] + shown[0], origin[1] + shown[1])
    weak, strong = theme.rgba("arrow"), theme.rgba("arrow_strong")
    colour = tuple(round(a + (b - a) * fraction) for a, b in zip(weak, strong))
    arcade.draw_line(origin[0], origin[1], end[0], end[1], colour, 0.12)
    head = 0.45
    left = (end[0] - ux * head - uy * head * 0.6, end[1] - uy * head + ux * head * 0.6)
    right = (end[0] - ux * head + uy * head * 0.6, end[1] - uy * head - ux * head * 0.6)
    arcade.draw_polygon_filled([end, left, right], colour)
    return fraction


def fit_camera(camera: arcade.Camera2D, bounds: tuple[float, float, float, float], width: int, height: int,
               hud: int = HUD_HEIGHT) -> None:
    """Zoom and centre the camera so the hole fills the window below the HUD bar."""
    x0, y0, x1, y1 = bounds
    w, h = x1 - x0 + 2 * MARGIN, y1 - y0 + 2 * MARGIN
    usable = max(1, height - hud)
    zoom = min(width / w, usable / h)
    camera.match_window()
    camera.zoom = zoom
    # Centre the hole in the area under the HUD.
    camera.position = ((x0 + x1) / 2, (y0 + y1) / 2 + hud / 2 / zoom)


PLAYER_COLOURS = (None, (79, 195, 247, 255), (239, 83, 80, 255), (186, 104, 200, 255))  # seat 1: the theme's


class PlayerBallArt(BallArt):
    """A player's ball: seat 1 in the theme's ball colour, the others in their own colour, so everyone
    on the green can tell whose ball is whose."""

    def __init__(self, outline: Sequence[polygon.Vec], theme: Theme, seat: int) -> None:
        super().__init__(outline, theme)
        self.colour = PLAYER_COLOURS[seat % len(PLAYER_COLOURS)] or theme.rgba("ball")
        if seat % len(PLAYER_COLOURS):
            local = list(outline)
            self.shapes = ShapeElementList()
            _filled(self.shapes, local, self.colour, theme.rgba("ball_edge"), 0.05)
            x, y = local[0]
            dot = 0.14 * polygon.bounding_radius(local)
            self.shapes.append(create_ellipse_filled(0.62 * x, 0.62 * y, dot, dot, theme.rgba("ball_edge")))


def draw_turn_ring(x: float, y: float, radius: float, colour) -> None:
    """A ring around the ball whose turn it is."""
    arcade.draw_circle_outline(x, y, radius * 1.45, colour, 0.07, num_segments=40)
