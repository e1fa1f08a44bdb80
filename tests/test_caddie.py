"""The search golfer at the player's side, headless: the first contact simulate_shots reports, the shot
preview up to it, the aim hint (from the worker process too), the computer opponent's turn in a
two-player round, the settings kept, and `autoplay` playing with the search golfer."""

from __future__ import annotations

import math
import shutil
import time
from concurrent.futures import Future

import pytest

from polygolf.engine.golf.holes import Course, find_course, load_all_courses
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.shots import Shot, simulate_shots
from polygolf.engine.loading.paths import HOLES_DIR, data_dir
from polygolf.game import golfer_process
from polygolf.game.caddie import SHOW_SECONDS, Caddie, ShotPreview, preview_path
from polygolf.game.golfer_process import GolferProcess, Question, answer, origin_of, question_for
from polygolf.game.session import Game, Round, RoundPlay, is_computer
from polygolf.game.shapes import CATALOGUE

PENTAGON = CATALOGUE[2][1]
FRAME = 1 / 60


@pytest.fixture(scope="module")
def meadow():
    return find_course(load_all_courses()[0], "meadow")


def _wall_distance(hole, point) -> float:
    """How far `point` is from the nearest wall outline."""
    best = math.inf
    for outline in hole.layout.wall_outlines():
        for a, b in zip(outline, outline[1:] + outline[:1]):
            ex, ey = b[0] - a[0], b[1] - a[1]
            t = max(0.0, min(1.0, ((point[0] - a[0]) * ex + (point[1] - a[1]) * ey) / (ex * ex + ey * ey)))
            best = min(best, math.hypot(point[0] - a[0] - t * ex, point[1] - a[1] - t * ey))
    return best


def _turn(a, b, c) -> float:
    """Degrees the direction of motion turns at b."""
    u, v = (b[0] - a[0], b[1] - a[1]), (c[0] - b[0], c[1] - b[1])
    if math.hypot(*u) < 1e-9 or math.hypot(*v) < 1e-9:
        return 0.0
    return abs(math.degrees(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])))


def test_simulate_shots_reports_the_first_contact_from_the_worlds_contacts(meadow):
    hole = meadow.holes[0]  # Straight: a wall above and below the tee
    tee = hole.layout.tee
    radius = hole.library.ball.radius
    up, along = Shot(tee, (0.3, 3.0)), Shot(tee, (2.0, 0.0))
    bounced, rolled = simulate_shots(hole, [up, along], "fast", path=True)
    contact = bounced.contact
    assert contact is not None and 2 < contact < len(bounced.path) - 1
    before = bounced.path[:contact]  # the points before it struck
    assert max(_turn(*before[k:k + 3]) for k in range(len(before) - 2)) < 0.5  # a straight line until then
    assert _turn(*bounced.path[contact - 2:contact + 1]) > 90  # and turns back from the wall in the next frame
    assert _wall_distance(hole, bounced.contact_at) < 0.01 < math.dist(bounced.contact_at, before[-1]) < 2 * radius
    assert rolled.contact is None and rolled.contact_at is None and rolled.holed  # into the cup: nothing struck
    # Followed only up to its contact: the same path, cut after the frame it struck in.
    cut, = simulate_shots(hole, [up], "fast", path=True, until_contact=True)
    assert (cut.contact, cut.contact_at) == (contact, bounced.contact_at) and cut.path == bounced.path[:contact + 1]
    assert simulate_shots(hole, [up], "fast")[0].contact is None  # asked only with the path


def test_the_preview_starts_at_the_ball_and_ends_at_the_first_contact(meadow):
    hole = meadow.holes[0]
    play = HolePlay(hole, PENTAGON, "balanced")
    try:
        ball = (play.ball.x, play.ball.y)
        arrow = (1.0, 2.4)  # up into the wall, then on
        path, contact = preview_path(play, PENTAGON, ball, arrow)
        assert path[0] == ball and contact is not None
        full, = simulate_shots(hole, [Shot(ball, arrow)], play.knobs, shape=PENTAGON, path=True)
        assert path[1:] == full.path[:full.contact] and contact == full.contact_at  # played, up to the bounce
        assert full.contact < len(full.path) - 5  # and the ball goes on after it
        _played_along(play, ball, arrow, path)  # played for real, the ball goes exactly along the preview
    finally:
        play.close()


def test_the_preview_knows_where_the_windmills_stand_now():
    hole = find_course(load_all_courses()[0], "hazards").holes[5]  # Windmill
    play = HolePlay(hole, PENTAGON, "fast")
    try:
        assert play.windmills
        play.step(97)  # the windmills have turned since the hole began; the ball rests on the tee
        ball = (play.ball.x, play.ball.y)
        cup = hole.layout.cup
        d = math.dist(ball, cup)
        arrow = (4.0 * (cup[0] - ball[0]) / d, 4.0 * (cup[1] - ball[1]) / d)  # hard, through the sweep
        path, contact = preview_path(play, PENTAGON, ball, arrow)
        as_at_start, = simulate_shots(hole, [Shot(ball, arrow)], "fast", shape=PENTAGON, path=True,
                                           until_contact=True)
        assert contact is not None and as_at_start.contact_at != contact  # a blade where it stands now
        _played_along(play, ball, arrow, path)
    finally:
        play.close()


def _played_along(play: HolePlay, ball, arrow, path) -> None:
    """The shot played for real goes through every point of the preview, bit for bit."""
    play.shoot(ball, arrow)
    for point in path[1:]:
        play.step()
        assert (play.ball.x, play.ball.y) == point


def test_the_preview_stops_at_another_players_ball(meadow):
    hole = meadow.holes[0]
    play = HolePlay(hole, PENTAGON, "fast", players=2)
    try:
        me, other = play.players[0].body, play.players[1].body
        toward = (other.x - me.x, other.y - me.y)
        path, contact = preview_path(play, PENTAGON, (me.x, me.y), toward)
        assert contact is not None and math.dist(contact, (other.x, other.y)) <= play.collider.radius + 0.01
        alone = HolePlay(hole, PENTAGON, "fast")
        alone.place_ball(me.x, me.y)
        try:  # without the other ball, the same shot runs on past it
            assert math.dist(preview_path(alone, PENTAGON, (me.x, me.y), toward)[0][-1], (me.x, me.y)) > \
                   math.dist(path[-1], (me.x, me.y)) + 1.0
        finally:
            alone.close()
    finally:
        play.close()


def test_the_preview_is_worked_out_again_only_when_the_arrow_moved_and_not_too_often(meadow):
    play = HolePlay(meadow.holes[0], PENTAGON, "fast")
    try:
        preview, ball = ShotPreview(), (play.ball.x, play.ball.y)
        assert preview.update(play, PENTAGON, ball, (2.0, 0.5), now=0.0)
        assert not preview.update(play, PENTAGON, ball, (2.5, 0.5), now=0.05)  # too soon
        assert not preview.update(play, PENTAGON, ball, (2.01, 0.5), now=0.5)  # hardly moved
        assert preview.update(play, PENTAGON, ball, (2.5, 0.5), now=0.5)
        assert preview.count == 2 and preview.cost < 0.5
    finally:
        play.close()


def test_the_hint_at_skill_1_sinks_the_straight_hole(meadow):
    hole = meadow.holes[0]
    play = HolePlay(hole, PENTAGON, "balanced")  # the game's preset; the hint searched at fast
    try:
        shot = answer(question_for(play, PENTAGON, skill=1.0))
        assert shot.start == hole.layout.tee
        play.shoot(origin_of(shot), shot.arrow)
        for _ in range(60 * 20):
            play.step()
            if play.state.finished or (play.ball_at_rest and play.state.strokes):
                break
        assert play.state.holed or math.dist((play.ball.x, play.ball.y), hole.layout.cup) < 1.0
    finally:
        play.close()


def test_the_search_plays_round_another_players_ball_in_its_way(meadow):
    """Hot seat: the other ball rests halfway along the straight line to the cup. The question
    carries it (an outline where it lies) and the search meets it as a wall, so the shot it picks
    goes round: played for real, the other ball is never struck and the ball drops. Asked without
    it, the search plays straight through it, and the shot is spoiled."""
    from dataclasses import replace

    hole = meadow.holes[0]
    outcomes = {}
    for told in (True, False):
        play = HolePlay(hole, PENTAGON, "balanced", players=2)
        try:
            me, other = play.players[0].body, play.players[1].body
            cup = hole.layout.cup
            halfway = (0.5 * (me.x + cup[0]), 0.5 * (me.y + cup[1]))
            play.turn = 1
            play.place_ball(*halfway)
            play.turn = 0
            question = question_for(play, PENTAGON, skill=1.0)
            outline, = question.others
            assert math.dist(_centre(outline), halfway) < 1e-9
            shot = answer(question if told else replace(question, others=()))
            play.shoot(origin_of(shot), shot.arrow)
            for _ in range(60 * 20):
                play.step()
                if play.all_at_rest:
                    break
            outcomes[told] = (math.dist((other.x, other.y), halfway), play.players[0].state.holed)
        finally:
            play.close()
    assert outcomes[True] == (0.0, True)
    moved, holed = outcomes[False]
    assert moved > 0.5 and not holed


def _centre(outline) -> tuple[float, float]:
    return sum(x for x, _ in outline) / len(outline), sum(y for _, y in outline) / len(outline)


def test_the_worker_process_answers_and_goes_away(meadow):
    golfers = GolferProcess()
    try:
        future = golfers.ask(Question(meadow.holes[0], PENTAGON, meadow.holes[0].layout.tee, 0.0, ()))
        shot = future.result(timeout=120)
        assert shot.start == meadow.holes[0].layout.tee and math.hypot(*shot.arrow) > 0.1
        process, = golfers._pool._processes.values()
    finally:
        golfers.close()
    # The executor's own thread reaps the worker too; until one of the two has, `is_alive` may say so.
    deadline = time.monotonic() + 3.0
    while process.is_alive() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not process.is_alive() and not golfers.started


class Controlled:
    """A golfer process whose answers the test hands out when it likes."""

    def __init__(self) -> None:
        self.asked: list[tuple[Question, Future]] = []

    def warm_up(self) -> None:
        pass

    def ask(self, question: Question) -> Future:
        future: Future = Future()
        self.asked.append((question, future))
        return future


def _round(meadow, players: list[str]) -> RoundPlay:
    return RoundPlay(Round(Course("meadow", "Meadow", meadow.holes[:1]), players=players), PENTAGON, "Pentagon",
                     "fast")


def test_a_hint_is_dropped_when_the_ball_moved_while_it_was_worked_out(meadow):
    session = _round(meadow, ["Ann"])
    golfers = Controlled()
    caddie = Caddie(session, golfers, hint="exact")
    caddie.update(FRAME)
    assert caddie.thinking and len(golfers.asked) == 1 and golfers.asked[0][0].skill == 1.0
    session.restart()  # the ball back on the tee with a penalty: another situation
    session.step()
    golfers.asked[0][1].set_result(answer(golfers.asked[0][0]))
    caddie.update(FRAME)
    assert caddie.shown_hint() is None and len(golfers.asked) == 2  # dropped, and asked again
    golfers.asked[1][1].set_result(answer(golfers.asked[1][0]))
    caddie.update(FRAME)
    assert caddie.shown_hint() is not None and not caddie.thinking
    assert caddie.toggle_hint() and caddie.shown_hint() is None  # H hides it ...
    assert caddie.toggle_hint() and caddie.shown_hint() is not None  # ... and shows it again, not searched again
    assert len(golfers.asked) == 2
    session.close()


def test_h_asks_for_a_hint_when_the_setting_is_off(meadow):
    session = _round(meadow, ["Ann"])
    golfers = Controlled()
    caddie = Caddie(session, golfers, hint="off")
    caddie.update(FRAME)
    assert not golfers.asked
    assert caddie.toggle_hint()
    caddie.update(FRAME)
    assert len(golfers.asked) == 1 and golfers.asked[0][0].skill == 0.8  # "good"
    session.close()


def test_the_computer_takes_its_turn_in_a_two_player_round(meadow):
    session = _round(meadow, ["Ann", "CPU"])
    assert [is_computer(n) for n in session.players] == [False, True]
    caddie = Caddie(session, GolferProcess(inline=True), hint="exact", computer_skill="exact")
    shown_at = None
    for frame in range(60 * 60):
        if session.hole_over:
            break
        if session.can_shoot and not session.computer_turn:
            caddie.update(FRAME)  # asked (inline: answered at once) ...
            caddie.update(FRAME)  # ... and collected
            hint = caddie.shown_hint()
            assert hint is not None  # the person gets the hint (inline: at once)
            assert session.shoot(origin_of(hint), hint.arrow)
        elif caddie.computer_arrow() is not None and shown_at is None:
            shown_at = frame
        if caddie.update(FRAME):
            assert frame - shown_at >= round(SHOW_SECONDS / FRAME) - 3  # its arrow was shown first
            assert caddie.shown_hint() is None  # no hint on the computer's turn
            shown_at = None
        session.step()
    assert session.hole_over
    shots = [(i.kind, i.player) for i in session.inputs]
    assert ("shot", 1) in shots and shots[:2] == [("shot", 0), ("shot", 1)]  # recorded like any shot
    assert all(p.state.holed for p in session.hole.players)
    session.close()


def test_the_assist_settings_are_kept_for_the_next_launch():
    game = Game.load()
    assert (game.hint, game.preview, game.computer_skill) == ("off", True, "good")
    game.next_hint()
    game.toggle_preview()
    game.next_computer_skill()
    again = Game.load()
    assert (again.hint, again.preview, again.computer_skill) == ("rough", False, "exact")
    game.store.save_settings(game.settings() | {"hint": "wild", "preview": "yes", "computer_skill": 3})
    assert (Game.load().hint, Game.load().preview, Game.load().computer_skill) == ("off", True, "good")


def test_only_names_that_say_cpu_are_the_computer():
    assert all(is_computer(n) for n in ("CPU", "cpu", "Cpu 2", "CPU the great"))
    assert not any(is_computer(n) for n in ("", "Ann", "CPUs", "my CPU"))


def test_autoplay_plays_with_the_search_golfer(monkeypatch, capsys):
    from polygolf.game.cli import main

    holes = data_dir() / "content" / "holes"
    holes.mkdir(parents=True)
    shutil.copy(HOLES_DIR / "straight.yaml", holes / "straight.yaml")
    (holes / "courses.yaml").write_text("courses:\n  - name: One Hole\n    holes: [straight]\n")
    asked = []

    def counted(question):
        asked.append(question)
        return answer(question)

    monkeypatch.setattr(golfer_process, "answer", counted)
    assert main(["autoplay", "--course", "One Hole", "--preset", "fast", "--skill", "1"]) == 0
    out = capsys.readouterr().out
    strokes = int(out.split(": ")[1].split()[0])
    assert asked and len(asked) == strokes and asked[0].knobs == "fast" and asked[0].skill == 1.0
    assert strokes < 3  # par 3
    with pytest.raises(SystemExit) as refused:
        main(["autoplay", "--course", "One Hole", "--skill", "1.5"])
    assert refused.value.code == 2 and "not a skill from 0 to 1" in capsys.readouterr().err
