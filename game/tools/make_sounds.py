"""Synthesises the game's sounds (game/sounds/*.wav) from numpy noise and sines, so they are ours to
ship (CC0; see game/sounds/LICENSE.md). Run it again after changing a recipe:

    python -m polygolf.game.tools.make_sounds [--out game/sounds]

Every sound is mono, 16-bit, 22 050 Hz and well under 50 KB; a fixed seed makes the files repeatable.
"""

from __future__ import annotations

import argparse
import wave
from collections.abc import Callable
from pathlib import Path

import numpy as np

RATE = 22_050
SEED = 12


def _time(seconds: float) -> np.ndarray:
    return np.arange(int(RATE * seconds)) / RATE


def _noise(rng: np.random.Generator, seconds: float) -> np.ndarray:
    return rng.uniform(-1.0, 1.0, int(RATE * seconds))


def _lowpass(signal: np.ndarray, cutoff: float) -> np.ndarray:
    """One-pole low-pass: enough to turn white noise into a thud or a wash."""
    alpha = 1.0 - np.exp(-2.0 * np.pi * cutoff / RATE)
    out = np.empty_like(signal)
    acc = 0.0
    for i, x in enumerate(signal):
        acc += alpha * (x - acc)
        out[i] = acc
    return out


def hit(rng: np.random.Generator) -> np.ndarray:
    """The putter on the ball: a bright click over a short hollow tone."""
    t = _time(0.18)
    tone = np.sin(2 * np.pi * 1250 * t) * np.exp(-t * 38) + 0.5 * np.sin(2 * np.pi * 2600 * t) * np.exp(-t * 60)
    click = _noise(rng, 0.18) * np.exp(-t * 260)
    return 0.7 * tone + 0.5 * click


def knock(rng: np.random.Generator) -> np.ndarray:
    """The ball against a wooden wall: a low knock, quickly damped."""
    t = _time(0.2)
    body = np.sin(2 * np.pi * 190 * t) * np.exp(-t * 30) + 0.6 * np.sin(2 * np.pi * 470 * t) * np.exp(-t * 45)
    thud = _lowpass(_noise(rng, 0.2), 1800) * np.exp(-t * 90) * 3.0
    return body + thud


def drop(rng: np.random.Generator) -> np.ndarray:
    """Into the cup: a rattle of three clicks on the rim, then a hollow thunk at the bottom."""
    t = _time(0.6)
    out = np.zeros_like(t)
    for start, pitch in ((0.0, 2100), (0.07, 1900), (0.12, 2300)):
        s = t - start
        on = s >= 0
        out[on] += 0.5 * np.sin(2 * np.pi * pitch * s[on]) * np.exp(-s[on] * 90)
    s = t - 0.2
    on = s >= 0
    out[on] += np.sin(2 * np.pi * 140 * s[on]) * np.exp(-s[on] * 14) + 0.4 * np.sin(2 * np.pi * 330 * s[on]) \
        * np.exp(-s[on] * 22)
    return out


def splash(rng: np.random.Generator) -> np.ndarray:
    """Into the water: a burst of washed noise with a few bubbles."""
    t = _time(0.7)
    wash = _lowpass(_noise(rng, 0.7), 2500) * np.minimum(1.0, t / 0.02) * np.exp(-t * 6) * 2.5
    bubbles = sum(0.25 * np.sin(2 * np.pi * (500 + 900 * k) * t * (1 + 2 * t)) * np.exp(-((t - 0.1 * k - 0.1) ** 2)
                                                                                     / 0.0008)
                  for k in range(4))
    return wash + bubbles


def boing(rng: np.random.Generator) -> np.ndarray:
    """A bumper: a springy tone that bends down and wobbles."""
    t = _time(0.45)
    pitch = 420 * np.exp(-t * 2.5) + 160 + 25 * np.sin(2 * np.pi * 14 * t)
    phase = 2 * np.pi * np.cumsum(pitch) / RATE
    return np.sin(phase) * np.exp(-t * 6) * np.minimum(1.0, t / 0.005)


def click(rng: np.random.Generator) -> np.ndarray:
    """A menu button: a short soft tick."""
    t = _time(0.06)
    return np.sin(2 * np.pi * 1800 * t) * np.exp(-t * 120) + 0.3 * _noise(rng, 0.06) * np.exp(-t * 400)


RECIPES: dict[str, Callable[[np.random.Generator], np.ndarray]] = {
    "hit": hit, "knock": knock, "drop": drop, "splash": splash, "boing": boing, "click": click,
}


def write_wav(path: Path, signal: np.ndarray, peak: float = 0.85) -> None:
    """Normalised to `peak` (the game scales loudness, not the file), faded out at the end."""
    fade = min(len(signal), int(RATE * 0.01))
    signal = signal.copy()
    signal[-fade:] *= np.linspace(1.0, 0.0, fade)
    samples = np.int16(np.round(signal / np.max(np.abs(signal)) * peak * 32767))
    with wave.open(str(path), "wb") as out:
        out.setnchannels(1)
        out.setsampwidth(2)
        out.setframerate(RATE)
        out.writeframes(samples.tobytes())


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=Path(__file__).resolve().parent.parent / "sounds")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    for name, recipe in RECIPES.items():
        path = args.out / f"{name}.wav"
        write_wav(path, recipe(np.random.default_rng(SEED)))
        print(f"{path}: {path.stat().st_size} bytes")


if __name__ == "__main__":
    main()
