"""Engine-wide tolerances, in SI units. The accuracy knobs a user may turn live in `presets`."""

FRAME_DT = 1.0 / 60.0  # one displayed frame; the preset splits it into substeps

LINEAR_SLOP = 0.005  # overlap tolerated without correction, m (keeps resting contacts still)
CONTACT_MARGIN = 2.0 * LINEAR_SLOP  # points closer than this are contacts, m
# m: a contact with a gap acts only if the motion would press in deeper than this (against a wall
# any gap is asked; two bodies, a gap wider than this)
GAP_TOLERANCE = 1e-4
TOI_TARGET = LINEAR_SLOP  # continuous collision stops a body this far from the surface, m
POSITION_BETA = 0.2  # fraction of the overlap removed per substep
MAX_CORRECTION = 0.1  # largest positional correction per substep, m
RESTITUTION_THRESHOLD = 0.05  # slower approaches do not bounce, m/s
BLOCK_MAX_CONDITION = 1000.0  # two-point manifolds worse conditioned than this are solved point by point

# Rest detection: a body that moves slower than these for TIME_TO_REST seconds is put to rest.
REST_LINEAR = 0.02  # m/s
REST_ANGULAR = 0.05  # rad/s
REST_SPEED_CAP = 0.1  # m/s; a body faster than this is never at rest, whatever its displacement
TIME_TO_REST = 0.25  # s

MAX_SHOT_SPEED = 25.0  # m/s; the fastest a shot can send the ball
MAX_SHOT_SPIN = 30.0  # rad/s; the angular part of a shot is capped on its own
SHOT_POWER = 5.0  # m/s of shot for each metre of arrow
SPIN_RATIO = 1.5  # a shot may spin the ball's rim at most this many times its linear speed
