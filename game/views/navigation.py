"""What a screen may ask of the screen flow (`game.flow.ScreenFlow`). Screens hold the flow and call
these; only the flow knows which screen comes next, so no screen imports another."""

from __future__ import annotations

from typing import Protocol

import arcade

from polygolf.game.session import Game, HoleResult


class Navigator(Protocol):
    def menu(self) -> None:
        """The main menu (any round in progress is abandoned)."""

    def new_round(self) -> None:
        """A round of the chosen course from its first hole (the guide first, if never seen); a Random
        nine not built yet is built first, its progress shown."""

    def names(self) -> None:
        """The players' names, then back to the menu."""

    def guide(self) -> None:
        """How to play, then back to the menu."""

    def pause(self, play: arcade.View) -> None:
        """The pause menu over the hole being played."""

    def resume(self, play: arcade.View) -> None:
        """Back to the hole being played."""

    def hole_done(self, results: list[HoleResult]) -> None:
        """A hole finished (every player's result): the between-holes screen, or, after the last, the
        round is saved and the scorecard shown."""

    def watch_last_shot(self, play: arcade.View) -> None:
        """The hole simulated again from its start and its last shot shown, then back to `play`."""

    def next_hole(self) -> None:
        """On to the round's next hole, or the scorecard if there is none."""

    def quit(self) -> None:
        """Close the game."""


def window_key(window: arcade.Window, game: Game, symbol: int) -> bool:
    """The keys every screen shares: F11 fullscreen, M mute. True if `symbol` was one of them."""
    if symbol == arcade.key.F11:
        window.set_fullscreen(not window.fullscreen)
        return True
    if symbol == arcade.key.M:
        game.toggle_mute()
        return True
    return False
