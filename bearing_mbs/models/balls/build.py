"""Builder of the ``balls`` model: discs, an optional floor and walls, and distance constraints."""

from __future__ import annotations

import math

from bearing_mbs.core.scene import GROUND, Body, ContactPair, DistanceConstraint, Scene
from bearing_mbs.core.topology import Group, Role, Topology
from bearing_mbs.models.balls.spec import COORDINATES
from bearing_mbs.models.building import pair_law, reject_initial_overlap
from bearing_mbs.spec import Spec


def ball_name(spec: Spec, index: int) -> str:
    return spec.balls[index].name or f"ball{index + 1}"


def constraint_lengths(spec: Spec) -> dict[tuple[int, int], float]:
    """(i, j) with i < j → constrained distance [m]; the initial distance where no length is given."""
    lengths = {}
    for c in spec.constraints:
        a, b = sorted(c.bodies)
        (xa, ya), (xb, yb) = spec.balls[a].position, spec.balls[b].position
        lengths[(a, b)] = c.length if c.length is not None else math.hypot(xb - xa, yb - ya)
    return lengths


def build_balls_scene(spec: Spec) -> Scene:
    """Bodies for the balls; a pair for each ball and each wall present; a pair for each two balls unless a
    rigid distance constraint keeps them apart; gravity only when it is non-zero."""
    bodies = tuple(
        Body(
            name=ball_name(spec, i),
            mass=ball.mass,
            inertia=ball.moment_of_inertia,
            position=(*ball.position, ball.angle),
            velocity=(*ball.velocity, ball.angular_velocity),
            free=tuple(c in ball.free for c in COORDINATES),
        )
        for i, ball in enumerate(spec.balls)
    )

    walls = []  # (name, point on the line, unit normal towards the inside of the box)
    box = spec.box
    if box is not None:
        if box.floor is not None:
            walls.append(("floor", (0.0, box.floor), (0.0, 1.0)))
        if box.left_wall is not None:
            walls.append(("left_wall", (box.left_wall, 0.0), (1.0, 0.0)))
        if box.right_wall is not None:
            walls.append(("right_wall", (box.right_wall, 0.0), (-1.0, 0.0)))

    pairs, blame, groups = [], [], {Group.WALL: [], Group.BALL: []}
    wall_law, ball_law = pair_law(spec.contact.wall), pair_law(spec.contact.ball)
    for i, ball in enumerate(spec.balls):
        for wall, point, normal in walls:
            groups[Group.WALL].append(len(pairs))
            pairs.append(
                ContactPair(
                    f"{bodies[i].name}-{wall}", "circle_line", GROUND, i, wall_law,
                    radius_b=ball.radius, anchor=point, direction=normal,
                )
            )
            blame.append(f"balls.{i}.position")
    lengths = constraint_lengths(spec)
    for i in range(len(spec.balls)):
        for j in range(i + 1, len(spec.balls)):
            if lengths.get((i, j), 0.0) >= spec.balls[i].radius + spec.balls[j].radius:
                continue  # the constraint keeps them apart: the pair could never touch
            groups[Group.BALL].append(len(pairs))
            pairs.append(
                ContactPair(
                    f"{bodies[i].name}-{bodies[j].name}", "circle_circle", i, j, ball_law,
                    radius_b=spec.balls[j].radius, radius_a=spec.balls[i].radius,
                )
            )
            blame.append(f"balls.{j}.position")

    constraints = [
        DistanceConstraint(f"{bodies[a].name}-{bodies[b].name} distance", a, b, length)
        for (a, b), length in lengths.items()
    ]

    scene = Scene(
        name=spec.scenario.name,
        bodies=bodies,
        pairs=tuple(pairs),
        constraints=tuple(constraints),
        gravity=(0.0, -spec.scenario.gravity),
        topology=Topology(bodies={Role.BALLS: range(len(bodies))}, pairs=groups),
    )
    reject_initial_overlap(scene, lambda k: blame[k])
    return scene
