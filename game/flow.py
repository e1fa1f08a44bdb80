"""The screen flow: the one place that decides which screen follows which.

    loading (the physics compiled or loaded) ─▶ menu, or the screen a command line asked for
    menu ─▶ (build Random nine, first time for a seed) ─▶ (guide, first time) ─▶ play ⇄ pause
    menu ─▶ menu, its problem listed: a course with no hole to play (every one broken)
    menu ⇄ names, guide
              play ─▶ between ─▶ play … ─▶ results ─▶ play again | menu
              play ⇄ replay (L: the last shot again)
    `polygolf replay FILE`: replay ─▶ results ─▶ menu

A finished round is saved (database and replay file) here, when the last hole is done.

Screens get this object and ask it to move on (`views.navigation.Navigator`); none imports another.
"""

from __future__ import annotations

from collections.abc import Callable

import arcade

from polygolf.engine.golf.holes import Course
from polygolf.game.building import NineBuild
from polygolf.game.record import RoundRecord
from polygolf.game.session import Game, HoleResult, Round, RoundPlay
from polygolf.game.views.between import BetweenView
from polygolf.game.views.build import BuildView
from polygolf.game.views.guide import GuideView
from polygolf.game.views.loading import LoadingView
from polygolf.game.views.menu import MenuView
from polygolf.game.views.names import NamesView
from polygolf.game.views.pause import PauseView
from polygolf.game.views.play import PlayView
from polygolf.game.views.replay import ReplayView
from polygolf.game.views.results import ResultsView


class ScreenFlow:
    def __init__(self, window: arcade.Window, game: Game) -> None:
        self.window = window
        self.game = game
        self.playing: PlayView | None = None

    def _show(self, view: arcade.View) -> arcade.View:
        self.window.show_view(view)
        return view

    def _leave_hole(self) -> None:
        if self.playing is not None:
            self.playing.close()
            self.playing = None

    def loading(self, then: Callable[[], None]) -> None:
        """The first screen of a window: the physics kernels compiled (first launch) or loaded, then
        `then` (the menu, or a hole straight away)."""
        self._show(LoadingView(self.game, then))

    def menu(self) -> None:
        self._leave_hole()
        self.game.close_session()
        self.game.round = None
        self._show(MenuView(self.game, self))

    def new_round(self, start_at: int = 0) -> None:
        self._leave_hole()
        if self.game.random_chosen and self.game.random_nine is None:
            # Built (and proven) first, with its progress shown; that screen comes back here when done.
            self._show(BuildView(self.game, NineBuild(self.game.random_seed).start(), self))
            return
        problem = self.game.unplayable(start_at)
        if problem is not None:  # every hole broken: no round (it would end at once, saved as played)
            self.game.show_problem(problem)
            self.menu()
            return
        self.game.start_round(start_at)
        if self.game.guide_seen:
            self.next_hole()
        else:
            self._show(GuideView(self.game, then=self.next_hole, back=self.menu))

    def names(self) -> None:
        self._show(NamesView(self.game, self))

    def guide(self) -> None:
        self._show(GuideView(self.game, then=self.menu))

    def pause(self, play: arcade.View) -> None:
        self._show(PauseView(self.game, play, self))

    def resume(self, play: arcade.View) -> None:
        self._show(play)

    def hole_done(self, results: list[HoleResult]) -> None:
        self.playing = None
        round_ = self.game.round
        if round_ is not None and round_.over and self.game.session is not None and self.game.record_rounds:
            self.game.save_round(self.game.session)
        if round_ is None or round_.over:
            self._show(ResultsView(self.game, round_, self))
        else:
            self._show(BetweenView(self.game, round_, results, self))

    def watch_last_shot(self, play: PlayView) -> None:
        """The hole being played simulated again from its start, unseen up to its last shot, which is
        shown; then back to the hole as it was."""
        session = play.session
        shot = session.last_shot()
        if shot is None or session.hole is None:
            return
        inputs = session.inputs
        inputs = inputs[:inputs.index(shot) + 1]
        hole = session.hole.hole
        again = RoundPlay(Round(Course(session.round.course.id, session.round.course.name, [hole]),
                                players=list(session.players)),
                          self.game.shape, self.game.shape_label, session.hole_preset,
                          feed={0: (session.hole_preset, inputs)})
        who = f"{session.players[shot.player]}'s" if len(session.players) > 1 else "Your"
        self._show(ReplayView(self.game, again, lambda: self.resume(play), f"{who} last shot",
                              from_frame=shot.frame, last_frame=shot.frame))

    def watch_round(self, record: RoundRecord, session: RoundPlay) -> None:
        """A recorded round shown hole by hole, then its scorecard."""
        def scorecard() -> None:
            self._show(ResultsView(self.game, session.round, self))

        when = record.recorded_at[:16].replace("T", " ")
        self._show(ReplayView(self.game, session, scorecard, f"Replay of {when} UTC"))

    def next_hole(self) -> None:
        round_ = self.game.round
        if round_ is None or round_.over:
            self._show(ResultsView(self.game, round_, self))
            return
        self.playing = PlayView(self.game, round_, self)
        self._show(self.playing)

    def replace_hole(self, index: int, hole) -> None:
        """A hole of the round's course was edited: the new one is played from now on."""
        self.game.course.holes[index] = hole
        if self.playing is not None and self.game.round is not None and self.game.round.position == index:
            self.playing.reload_hole()

    def quit(self) -> None:
        self._leave_hole()
        self.window.close()
