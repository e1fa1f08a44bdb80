"""Sound, tested by what is played: real holes are played through the HolePlay facade and the
events they report go to a SoundBoard whose player records (name, volume)."""

from __future__ import annotations

import math

import pytest

from polygolf.engine.golf.golfer import golfer_for
from polygolf.engine.golf.holes import find_course, load_all_courses
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.game.sound import QUIETEST, SOUND_NAMES, SOUNDS_DIR, ArcadePlayer, SoundBoard, loudness

SQUARE = ShapeSpec(regular=4, radius=1.0)


class RecordingPlayer:
    def __init__(self) -> None:
        self.played: list[tuple[str, float]] = []

    def play(self, name: str, volume: float) -> None:
        self.played.append((name, volume))

    def volumes(self, name: str) -> list[float]:
        return [v for n, v in self.played if n == name]


@pytest.fixture(scope="module")
def courses():
    return load_all_courses()[0]


def hole(courses, course: str, number: int):
    return find_course(courses, course).holes[number - 1]


def play_shot(world: HolePlay, board: SoundBoard, arrow, origin=None, max_frames: int = 600) -> None:
    """Shoot and let the ball run until it rests or drops, the board hearing every frame."""
    world.shoot(origin or (world.ball.x, world.ball.y), arrow)
    for _ in range(max_frames):
        world.step()
        board.hear(*world.drain_events())
        if world.ball_at_rest or world.state.holed:
            return


def shot_into_the_south_wall(courses, arrow_length: float) -> RecordingPlayer:
    world = HolePlay(hole(courses, "meadow", 1), SQUARE)
    try:
        player = RecordingPlayer()
        play_shot(world, SoundBoard(player, volume=1.0), (0.0, -arrow_length), max_frames=90)
        return player
    finally:
        world.close()


def test_a_harder_shot_hits_and_knocks_louder(courses):
    soft, hard = shot_into_the_south_wall(courses, 1.0), shot_into_the_south_wall(courses, 4.0)
    assert soft.volumes("hit") and hard.volumes("hit")
    assert hard.volumes("hit")[0] > soft.volumes("hit")[0] >= QUIETEST
    assert soft.volumes("knock") and hard.volumes("knock")
    assert max(hard.volumes("knock")) > max(soft.volumes("knock")) + 0.2
    assert max(hard.volumes("knock")) <= 1.0


def test_the_ball_dropping_plays_the_drop(courses):
    world = HolePlay(hole(courses, "meadow", 1), SQUARE)
    try:
        player = RecordingPlayer()
        board = SoundBoard(player, volume=0.5)
        golfer = golfer_for(world.hole)
        for _ in range(6):
            if world.state.holed:
                break
            origin, arrow = golfer.plan((world.ball.x, world.ball.y))
            play_shot(world, board, arrow, origin)
        assert world.state.holed
        assert player.volumes("drop") == [0.5]  # once, at the board's volume
        assert [n for n, _ in player.played].index("drop") > [n for n, _ in player.played].index("hit")
    finally:
        world.close()


def test_water_plays_the_splash(courses):
    world = HolePlay(hole(courses, "hazards", 2), SQUARE)  # Water Carry: the pond is east of the tee
    try:
        player = RecordingPlayer()
        play_shot(world, SoundBoard(player), (1.6, 0.0))
        assert world.state.penalties == 1
        assert len(player.volumes("splash")) == 1
    finally:
        world.close()


def test_a_restart_costs_a_stroke_but_splashes_nothing(courses):
    """Back to the tee is a penalty stroke, as water is, but not water's splash (QA: R on a dry hole
    played it). A restart mid-roll, then one at rest."""
    world = HolePlay(hole(courses, "meadow", 1), SQUARE)
    try:
        player = RecordingPlayer()
        board = SoundBoard(player)
        world.shoot((world.ball.x, world.ball.y), (0.0, 1.0))
        for _ in range(10):
            world.step()
            board.hear(*world.drain_events())
        for _ in range(2):
            assert world.restart_ball()
            world.step()
            board.hear(*world.drain_events())
        assert (world.state.strokes, world.state.penalties) == (1, 2)
        assert player.volumes("splash") == [] and len(player.volumes("hit")) == 1
    finally:
        world.close()


def test_a_bumper_plays_boing_and_a_wall_knocks(courses):
    world = HolePlay(hole(courses, "hazards", 5), SQUARE)  # Pinball Wizard
    try:
        player = RecordingPlayer()
        bx, by = min((sum(x for x, _ in o) / len(o), sum(y for _, y in o) / len(o))
                     for o, _, _ in world.layout.bumpers)
        ball = world.ball
        d = math.hypot(bx - ball.x, by - ball.y)
        play_shot(world, SoundBoard(player), ((bx - ball.x) / d * 3.0, (by - ball.y) / d * 3.0))
        assert player.volumes("boing")
        assert all(0.0 < v <= 1.0 for _, v in player.played)
    finally:
        world.close()


def test_muted_or_silent_boards_play_nothing_and_volume_scales(courses):
    player = RecordingPlayer()
    board = SoundBoard(player, volume=0.5)
    board.click()
    board.toggle_mute()
    board.click()
    assert player.played == [("click", pytest.approx(0.3))]
    assert board.next_volume() == 0.75 and not board.muted
    assert loudness(0.1, 10.0) == 0.0 and loudness(10.0, 10.0) == 1.0 and loudness(50.0, 10.0) == 1.0


def test_one_sound_per_kind_a_frame_at_its_loudest():
    from polygolf.engine.components.resources import Impact

    player = RecordingPlayer()
    SoundBoard(player, volume=1.0).hear([], [Impact("wall", 2.0, 0, 0), Impact("wall", 6.0, 0, 0),
                                              Impact("body", 1.0, 0, 0)])
    assert player.played == [("knock", loudness(6.0, 10.0))]


def test_a_chattering_ball_knocks_a_few_times_not_every_frame():
    from polygolf.engine.components.resources import Impact

    player = RecordingPlayer()
    board = SoundBoard(player, volume=1.0)
    for _ in range(30):  # half a second of light wall touches, every frame
        board.hear([], [Impact("wall", 1.0, 0, 0)])
    board.hear([], [Impact("wall", 8.0, 0, 0)])  # a real hit straight after is heard at once
    volumes = player.volumes("knock")
    assert 5 <= len(volumes) - 1 <= 8  # one every REPEAT_GAP (0.08 s) of the 0.5 s
    assert volumes[-1] == loudness(8.0, 10.0)


def test_the_sounds_ship_small_and_a_player_without_them_goes_silent(tmp_path, capsys):
    for name in SOUND_NAMES:
        assert 0 < (SOUNDS_DIR / f"{name}.wav").stat().st_size < 50_000
    player = ArcadePlayer(tmp_path)  # no files here: loading fails
    player.play("hit", 1.0)
    player.play("hit", 1.0)
    assert player.failed
    assert capsys.readouterr().err.count("no sound") == 1


def test_the_real_player_plays_or_goes_silent_but_never_raises():
    player = ArcadePlayer()
    for name in SOUND_NAMES:
        player.play(name, 0.5)
    assert player.failed or player.sounds is not None
