"""The search golfer in the real window (Xvfb): the aim hint worked out in the worker process while the
window goes on, the shot preview while dragging, and the computer's turn, each drawn to a PNG; the
menu's and the Names screen's settings for them."""

from __future__ import annotations

import time

import arcade
import numpy as np
import pytest

from polygolf.engine.golf.golfer import golfer_for
from polygolf.game.flow import ScreenFlow
from polygolf.game.golfer_process import origin_of
from polygolf.game.session import Game
from polygolf.game.views.play import PlayView

from .test_screens import aim, assert_not_blank, click, key, send, shots_dir, snapshot, window  # noqa: F401

WAIT = 90.0  # s: a search takes 1-6 s of CPU, plus the worker's start; the machine may be busy


def play_round(win, players: list[str], hint: str = "off") -> tuple[Game, PlayView]:
    game = Game.load()
    game.guide_seen, game.hint, game.players, game.computer_skill = True, hint, players, "exact"
    ScreenFlow(win, game).new_round()  # Meadow, hole 1 (Straight)
    view = win.current_view
    assert isinstance(view, PlayView)
    return game, view


def run_until(view: PlayView, done, seconds: float = WAIT, seen=None) -> float:
    """Frames in real time (the worker needs it) until `done()`; `seen(view)` looks at every frame."""
    start = last = time.perf_counter()
    while not done():
        time.sleep(1 / 120)
        now = time.perf_counter()
        view.on_update(min(now - last, 0.05))
        last = now
        if seen is not None:
            seen(view)
        if now - start > seconds:
            pytest.fail(f"not done in {seconds:.0f} s")
    return time.perf_counter() - start


def test_the_hint_comes_while_the_window_runs_and_the_preview_follows_the_drag(window, shots_dir):  # noqa: F811
    game, play = play_round(window, ["Ann"], hint="exact")
    try:
        frames = []
        waited = run_until(play, lambda: play.caddie.shown_hint() is not None,
                           seen=lambda v: frames.append(v.hud_texts["strokes"].text))
        assert any("thinking…" in text for text in frames)  # said while the worker searched
        assert len(frames) > 10  # and the window went on meanwhile (frames every 1/120 s of waiting)
        assert "thinking…" not in play.hud_texts["strokes"].text
        with_hint = snapshot(window, shots_dir, "play-hint")
        assert_not_blank(with_hint, "play")
        key(window, arcade.key.H)  # hides it
        assert play.caddie.shown_hint() is None
        assert np.abs(with_hint - snapshot(window, shots_dir, "play-hint-hidden")).mean() > 0.05
        key(window, arcade.key.H)
        hint = play.caddie.shown_hint()
        assert hint is not None and waited < WAIT
        # Drag the hinted arrow: the dotted preview from the ball, up to its first bounce or rest.
        ball = play.world.ball
        tee = (ball.x, ball.y)
        aim(window, play, origin_of(hint), hint.arrow, release=False)
        play.on_update(1 / 60)
        assert play.preview.path[0] == tee and len(play.preview.path) > 10 and play.preview_art is not None
        assert_not_blank(snapshot(window, shots_dir, "play-preview"), "play")
        key(window, arcade.key.P)  # the preview off, at once
        assert not game.preview and play.preview_art is None and not play.preview.path
        play.on_update(1 / 60)
        assert play.preview_art is None
        key(window, arcade.key.P)
        play.on_update(1 / 60)
        assert play.preview_art is not None
        x, y = play.camera.project((play.tip[0], play.tip[1]))[:2]
        send(window, "on_mouse_release", x, y, arcade.MOUSE_BUTTON_LEFT, 0)
        assert play.session.inputs[-1].player == 0 and not play.preview.path
        run_until(play, lambda: play.session.hole_over or play.session.can_shoot, 30)
        assert play.world.state.holed or play.world.state.strokes == 1
    finally:
        game.close()


def test_the_computer_shows_its_arrow_then_shoots_like_a_player(window, shots_dir):  # noqa: F811
    game, play = play_round(window, ["Ann", "CPU"])
    try:
        world = play.world
        origin, arrow = golfer_for(world.hole).plan((world.ball.x, world.ball.y))
        aim(window, play, origin, (arrow[0] * 0.5, arrow[1] * 0.5))  # Ann: short, so the hole goes on
        run_until(play, lambda: play.session.can_shoot, 30)
        assert play.session.computer_turn and play.hud_texts["strokes"].text.startswith("CPU: 0 strokes")
        assert "Ann: 1" in play.hud_texts["players"].text and "CPU: 0" in play.hud_texts["players"].text
        thinking = []
        run_until(play, lambda: play.caddie.computer_arrow() is not None and play.caddie.shown > 0.6,
                  seen=lambda v: thinking.append("thinking…" in v.hud_texts["strokes"].text))
        assert any(thinking)
        assert_not_blank(snapshot(window, shots_dir, "play-computer-turn"), "play")
        # A player's press does nothing on the computer's turn; R says why it does nothing.
        send(window, "on_mouse_press", *play.camera.project((world.ball.x, world.ball.y))[:2],
                              arcade.MOUSE_BUTTON_LEFT, 0)
        assert not play.aiming
        send(window, "on_key_press", arcade.key.R, 0)
        assert play.banner.text == "The computer's ball is the computer's to restart" and world.state.penalties == 0
        run_until(play, lambda: len(play.session.inputs) == 2, 5)
        shot = play.session.inputs[-1]
        assert (shot.kind, shot.player) == ("shot", 1)  # recorded like any shot
        run_until(play, lambda: play.session.hole_over or (play.session.can_shoot and not play.session.computer_turn),
                  30)
        assert "CPU: 1" in play.hud_texts["players"].text
        snapshot(window, shots_dir, "play-after-computer")
    finally:
        game.close()


def test_the_menu_and_names_screen_set_the_helpers(window, shots_dir):  # noqa: F811
    game = Game.load()
    game.players = ["Ann", "Bob"]
    ScreenFlow(window, game).menu()
    click(window, "hint")
    click(window, "preview")
    menu = window.current_view
    assert menu.buttons["hint"].text == "Hint: rough" and menu.buttons["preview"].text == "Preview: off"
    assert_not_blank(snapshot(window, shots_dir, "menu-helpers"), "menu")
    click(window, "names")
    names = window.current_view
    click(window, names.toggles[1])
    assert [box.text for box in names.boxes] == ["Ann", "CPU"] and names.toggles[1].text == "Computer"
    click(window, names.skill)
    assert names.skill.text == "Computer plays: exact"
    assert_not_blank(snapshot(window, shots_dir, "names-computer"), "names")
    key(window, arcade.key.ENTER)
    again = Game.load()
    assert (again.hint, again.preview, again.players, again.computer_skill) == ("rough", False, ["Ann", "CPU"],
                                                                                "exact")
