"""What the game sounds like: game events and impacts become named sounds at a loudness.

The `SoundBoard` decides what is heard (testable: give it a recording player); a `Player` only plays
a name at a volume. `ArcadePlayer` plays the shipped WAVs (game/sounds, CC0) through arcade; if the
machine has no audio device, or a file cannot be loaded, it says so once and goes silent: sound never
stops the game.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Protocol

from polygolf.engine.components.resources import Impact
from polygolf.engine.physics.settings import FRAME_DT, MAX_SHOT_SPEED

SOUNDS_DIR = Path(__file__).resolve().parent / "sounds"
SOUND_NAMES = ("hit", "knock", "drop", "splash", "boing", "click")

AUDIBLE_SPEED = 0.3  # m/s: a softer touch on a wall is not heard
LOUDEST_KNOCK_SPEED = 10.0  # m/s: a wall hit this fast (or faster) knocks at full volume
QUIETEST = 0.12  # the loudness of the softest sound still played (a whisper, not nothing)
VOLUME_STEPS = (0.0, 0.25, 0.5, 0.75, 1.0)
REPEAT_GAP = 0.08  # game seconds: the same sound again this soon only if louder (a ball chattering
# along a wall knocks a few times, not sixty times a second)

IMPACT_SOUNDS = {"shot": ("hit", MAX_SHOT_SPEED), "wall": ("knock", LOUDEST_KNOCK_SPEED),
                 "body": ("knock", LOUDEST_KNOCK_SPEED), "bumper": ("boing", LOUDEST_KNOCK_SPEED)}
EVENT_SOUNDS = {"holed": "drop", "penalty": "splash"}


class Player(Protocol):
    def play(self, name: str, volume: float) -> None:
        """Play the sound `name` at `volume` (0 to 1)."""


def loudness(speed: float, loudest: float) -> float:
    """How loud a hit at `speed` sounds: QUIETEST at the audible threshold up to 1 at `loudest`, by the
    square root (loudness is heard roughly logarithmically; a linear ramp makes soft hits inaudible)."""
    if speed < AUDIBLE_SPEED:
        return 0.0
    fraction = min(1.0, (speed - AUDIBLE_SPEED) / (loudest - AUDIBLE_SPEED))
    return QUIETEST + (1.0 - QUIETEST) * math.sqrt(fraction)


class SoundBoard:
    """Maps what happened to what is played, at the player's volume; M mutes."""

    def __init__(self, player: Player, volume: float = 0.75, muted: bool = False) -> None:
        self.player = player
        self.volume = volume
        self.muted = muted
        self.time = 0.0  # game seconds heard so far
        self.last: dict[str, tuple[float, float]] = {}  # sound -> (when, loudness) it last played in `hear`

    def play(self, name: str, loudness_: float = 1.0) -> None:
        level = loudness_ * self.volume
        if level > 0.0 and not self.muted:
            self.player.play(name, level)

    def hear(self, events: Iterable[tuple[str, int, int]], impacts: Iterable[Impact],
             seconds: float = FRAME_DT) -> None:
        """One frame's (`seconds` of game time) golf events and impacts: each sound at most once a frame,
        at its loudest (a face landing flat on a wall is one knock, not one per substep), and not again
        within REPEAT_GAP unless louder."""
        self.time += seconds
        loudest: dict[str, float] = {}
        for impact in impacts:
            name, full = IMPACT_SOUNDS.get(impact.kind, ("knock", LOUDEST_KNOCK_SPEED))
            loudest[name] = max(loudest.get(name, 0.0), loudness(impact.speed, full))
        for kind, _ball, _amount in events:
            if kind in EVENT_SOUNDS:
                loudest[EVENT_SOUNDS[kind]] = 1.0
        for name, level in loudest.items():
            when, before = self.last.get(name, (-REPEAT_GAP, 0.0))
            if level > 0.0 and (self.time - when >= REPEAT_GAP or level > before):
                self.last[name] = (self.time, level)
                self.play(name, level)

    def click(self) -> None:
        self.play("click", 0.6)

    def toggle_mute(self) -> bool:
        self.muted = not self.muted
        return self.muted

    def next_volume(self) -> float:
        """The next of VOLUME_STEPS (after the loudest, silence again); unmutes."""
        above = [step for step in VOLUME_STEPS if step > self.volume + 1e-6]
        self.volume = above[0] if above else VOLUME_STEPS[0]
        self.muted = False
        return self.volume


class SilentPlayer:
    def play(self, name: str, volume: float) -> None:
        pass


class ArcadePlayer:
    """Plays the shipped WAVs with arcade, loading them on first use. Any failure (no audio device,
    a missing file) is reported once on stderr and the player goes silent for good."""

    def __init__(self, folder: Path = SOUNDS_DIR) -> None:
        self.folder = folder
        self.sounds: dict[str, object] | None = None
        self.failed = False

    def _load(self) -> dict[str, object]:
        import arcade
        from pyglet.media import get_audio_driver

        driver = get_audio_driver()
        if driver is None or type(driver).__name__ == "SilentDriver":
            # Its players cost a thread's time each and are heard by nobody.
            raise RuntimeError("no audio device (pyglet fell back to its silent driver)")
        return {name: arcade.Sound(self.folder / f"{name}.wav") for name in SOUND_NAMES}

    def play(self, name: str, volume: float) -> None:
        if self.failed:
            return
        try:
            if self.sounds is None:
                self.sounds = self._load()
            self.sounds[name].play(volume=volume)  # type: ignore[attr-defined]
        except Exception as exc:  # pyglet raises several kinds when there is no device or driver
            self.failed = True
            print(f"polygolf: no sound ({type(exc).__name__}: {exc})", file=sys.stderr)
