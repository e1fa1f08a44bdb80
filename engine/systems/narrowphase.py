import esper

from engine.collide import collide_polygons
from engine.components import Body, Collider, Material, Wall
from engine.contact import ContactPoint, Manifold, group_by_normal, make_point, reduce_points
from engine.context import PhysicsContext
from engine.settings import CONTACT_MARGIN, RESTITUTION_THRESHOLD


def combine(a: Material, b: Material) -> Material:
    """Materials multiply (design notes): walls default to 1.0, so the ball's own values rule."""
    return Material(restitution=a.restitution * b.restitution, friction=a.friction * b.friction)


class NarrowphaseProcessor(esper.Processor):
    """Manifolds for the broadphase's candidates: separating axes and clipping on every pair of convex
    pieces, then all points between the same two bodies that share a normal become one manifold of at
    most two points. Impulses of points that persist are carried over for warm starting."""

    name = "narrowphase"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        ctx = self.ctx
        knobs = ctx.knobs
        previous: dict[tuple, tuple[float, float]] = {}
        if knobs.warm_start:
            # Only persistent contacts are warm-started: an impact's impulse belongs to that impact,
            # and re-applying it to a contact that is now opening would add energy.
            for m in ctx.manifolds:
                for p in m.points:
                    if (p.normal_impulse or p.tangent_impulse) and p.approach_speed >= -RESTITUTION_THRESHOLD:
                        previous[(m.entity_a, m.entity_b, p.key)] = (p.normal_impulse, p.tangent_impulse)
        ngs = knobs.position_correction == "ngs"
        manifolds: list[Manifold] = []
        deepest = ctx.max_penetration
        static = ctx.static_body

        for ent, found in ctx.wall_candidates.items():
            body, col = esper.component_for_entity(ent, Body), esper.component_for_entity(ent, Collider)
            pieces, normals = col.world(body.x, body.y, body.angle)
            raw: list[tuple[float, float, ContactPoint]] = []
            for wall_ent, k in found:
                wall = esper.component_for_entity(wall_ent, Wall)
                wall_verts, wall_normals = wall.pieces[k], wall.normals[k]
                material = None
                for i in range(len(pieces)):
                    hit = collide_polygons(pieces[i], normals[i], wall_verts, wall_normals, CONTACT_MARGIN)
                    if hit is None:
                        continue
                    normal, contacts = hit
                    material = material or combine(col.material, wall.material)
                    for rc in contacts:
                        raw.append((normal[0], normal[1],
                                    make_point(rc, normal, (wall_ent, k, i, rc.feature), body, static, material, ngs)))
            if raw:
                deepest = self._emit(manifolds, raw, ent, -1, body, static, previous, deepest)

        for ea, eb in ctx.body_pairs:
            a, col_a = esper.component_for_entity(ea, Body), esper.component_for_entity(ea, Collider)
            b, col_b = esper.component_for_entity(eb, Body), esper.component_for_entity(eb, Collider)
            reach = col_a.radius + col_b.radius + CONTACT_MARGIN
            if (a.x - b.x) ** 2 + (a.y - b.y) ** 2 > reach * reach:
                continue
            pieces_a, normals_a = col_a.world(a.x, a.y, a.angle)
            pieces_b, normals_b = col_b.world(b.x, b.y, b.angle)
            material = combine(col_a.material, col_b.material)
            raw = []
            for i in range(len(pieces_a)):
                for j in range(len(pieces_b)):
                    hit = collide_polygons(pieces_a[i], normals_a[i], pieces_b[j], normals_b[j], CONTACT_MARGIN)
                    if hit is None:
                        continue
                    normal, contacts = hit
                    for rc in contacts:
                        point = make_point(rc, normal, (j, i, rc.feature), a, b, material, ngs)
                        raw.append((normal[0], normal[1], point))
            if raw:
                if a.asleep or b.asleep:
                    a.wake()
                    b.wake()
                deepest = self._emit(manifolds, raw, ea, eb, a, b, previous, deepest)

        ctx.manifolds = manifolds
        ctx.touching = {m.entity_a for m in manifolds} | {m.entity_b for m in manifolds}
        ctx.max_penetration = deepest

    @staticmethod
    def _emit(manifolds: list[Manifold], raw: list, ea: int, eb: int, a: Body, b: Body,
              previous: dict, deepest: float) -> float:
        for nx, ny, points in group_by_normal(raw):
            points = reduce_points(points, nx, ny)
            for p in points:
                if -p.separation > deepest:
                    deepest = -p.separation
                carried = previous.get((ea, eb, p.key))
                if carried is not None:
                    p.normal_impulse, p.tangent_impulse = carried
            manifolds.append(Manifold(entity_a=ea, entity_b=eb, body_a=a, body_b=b, nx=nx, ny=ny, points=points))
        return deepest
