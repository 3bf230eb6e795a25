#!/usr/bin/env python3
"""Writes the shipped scenes of data/scenes (deterministic: fixed seeds, no third-party modules).

    python3 data/scenes/make_scenes.py        # rewrites the *.json next to this script

Conventions: y is up, the ground is the plane y = 0, the default camera looks down -z.
A "direction" is the way the light travels; elevation is measured above the horizon.
"""
import json
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))


def r3(x):
    return round(x, 3) + 0.0  # + 0.0 turns -0.0 into 0.0


def vec(*xs):
    return [r3(x) for x in xs]


def from_angles(azimuth_deg, elevation_deg):
    """Unit vector; azimuth 0 is -z (the default view direction), 90 is +x; elevation up."""
    a, e = math.radians(azimuth_deg), math.radians(elevation_deg)
    return (math.cos(e) * math.sin(a), math.sin(e), -math.cos(e) * math.cos(a))


def travelling(azimuth_deg, elevation_deg):
    """Direction of light coming from the sky at the given azimuth and elevation."""
    return vec(*(-c for c in from_angles(azimuth_deg, elevation_deg)))


def camera(position, view, fov=60, aspect=16 / 9, near=0.5, far=400):
    """A camera at `position` looking along `view` (target 10 units ahead)."""
    target = [p + 10 * v for p, v in zip(position, view)]
    return {"position": vec(*position), "target": vec(*target), "up": [0, 1, 0],
            "fov_y_deg": fov, "aspect": r3(aspect), "near": near, "far": far}


def named(obj, name):
    """The object with a name, placed after its type."""
    return {"type": obj["type"], "name": name, **obj}


def ground(size):
    return {"type": "plane", "name": "ground", "size": [size, size], "casts": False}


# ---- the town ---------------------------------------------------------------------------------

def house(rng, x, z):
    w, d, h = rng.uniform(4, 12), rng.uniform(4, 12), rng.uniform(2, 10)
    return {"type": "box", "position": vec(x, h / 2, z), "rotation": vec(0, rng.uniform(0, 90), 0),
            "size": vec(w, h, d)}


def tower(rng, x, z, low=15, high=40):
    w, h = rng.uniform(4, 9), rng.uniform(low, high)
    return {"type": "box", "position": vec(x, h / 2, z), "rotation": vec(0, rng.uniform(0, 90), 0),
            "size": vec(w, h, rng.uniform(4, 9))}


def tank(rng, x, z):
    r, h = rng.uniform(2, 5), rng.uniform(3, 8)
    return {"type": "cylinder", "position": vec(x, h / 2, z), "radius": r3(r), "height": r3(h)}


def tree(rng, x, z):
    """A trunk and a crown."""
    h, r = rng.uniform(1.5, 3), rng.uniform(1.2, 2.5)
    return [{"type": "cylinder", "position": vec(x, h / 2, z), "radius": 0.25, "height": r3(h)},
            {"type": "sphere", "position": vec(x, h + 0.8 * r, z), "radius": r3(r)}]


def building(rng, x, z):
    roll = rng.random()
    if roll < 0.62:
        return [house(rng, x, z)]
    if roll < 0.80:
        return [tower(rng, x, z)]
    if roll < 0.88:
        return [tank(rng, x, z)]
    return tree(rng, x, z)


def town(rng, count, half_extent, keep_clear=None, lot=16.0):
    """About `count` objects on a grid of lots with streets between them, within +-half_extent;
    keep_clear(x, z) -> True leaves a lot empty (e.g. where the camera stands)."""
    lots = []
    n = int(half_extent // lot)
    for i in range(-n, n):
        for j in range(-n, n):
            x, z = (i + 0.5) * lot, (j + 0.5) * lot
            if not (keep_clear and keep_clear(x, z)):
                lots.append((x, z))
    rng.shuffle(lots)
    objects = []
    jitter = lot * 0.15
    for x, z in lots:
        new = building(rng, x + rng.uniform(-jitter, jitter), z + rng.uniform(-jitter, jitter))
        if len(objects) + len(new) > count:  # never a trunk without its crown
            break
        objects += new
    return objects


def near_street(x0, width):
    """keep_clear for a street along z at x = x0."""
    return lambda x, z: abs(x - x0) < width


# ---- scenes -----------------------------------------------------------------------------------

def scene(name, description, cam, light, objects, ground_size):
    return {"name": name, "description": description, "camera": cam, "light": light,
            "objects": [ground(ground_size)] + objects}


DEFAULT_SUN_AZIMUTH, DEFAULT_SUN_ELEVATION = 55, 17


def default(rng):
    return scene(
        "default", "A small town at sunset, seen from the street: low sun from the front right.",
        camera((0, 2.5, 190), from_angles(3, -1.5)),
        {"type": "directional", "direction": travelling(DEFAULT_SUN_AZIMUTH, DEFAULT_SUN_ELEVATION)},
        town(rng, 400, 200, near_street(0, 10), lot=18), 400)


def default_town_under(name, description, light):
    """The default scene, its town drawn from default's own seed, under another light."""
    return {**default(random.Random(seed_of(default))), "name": name, "description": description, "light": light}


def grazing_sun(rng):
    return default_town_under(
        "grazing_sun",
        "The default town under a grazing sun, 0.5 deg above the horizon at the default azimuth: "
        "the depth bias's hardest case (acne on the ground against peter panning of long shadows).",
        {"type": "directional", "direction": travelling(DEFAULT_SUN_AZIMUTH, 0.5)})


def overhead_view(rng):
    return {**default_town_under(
        "overhead_view",
        "The default town and sun seen from 60 above at 50 deg down, far / near = 1,000: "
        "a street's shadows up close and the whole town to the horizon in one view.",
        {"type": "directional", "direction": travelling(DEFAULT_SUN_AZIMUTH, DEFAULT_SUN_ELEVATION)}),
        "camera": camera((0, 60, 230), from_angles(0, -50), near=0.4, far=400)}


def sun_disc(rng):
    return default_town_under(
        "sun_disc",
        "The default town under a sun of its real size, a disc 0.5 deg in radius: soft shadows, "
        "penumbrae growing with the distance from the caster.",
        {"type": "directional", "direction": travelling(DEFAULT_SUN_AZIMUTH, DEFAULT_SUN_ELEVATION),
         "angular_radius_deg": 0.5})


def small_town(rng, count=60, street=0):
    return town(rng, count, 64, near_street(street, 10))


def light_parallel_behind(rng):
    view = from_angles(0, -25)
    return scene(
        "light_parallel_behind",
        "Light from behind the viewer, 1 degree off the view direction (camera looks down 25 deg).",
        camera((0, 30, 80), view, far=200),
        {"type": "directional", "direction": vec(*from_angles(0.6, -25.8))},  # 1.0 deg off view
        small_town(rng), 160)


def light_parallel_front(rng):
    return scene(
        "light_parallel_front",
        "Light toward the viewer, 1 degree off the opposite of the view direction: low sun ahead.",
        camera((0, 2, 70), from_angles(0, 10), far=200),
        {"type": "directional", "direction": travelling(0.6, 10.8)},  # 1.0 deg off -view
        small_town(rng), 160)


def casters_behind(rng):
    towers = [named(tower(rng, x, z, 30, 60), "tower_behind_%d" % i)
              for i, (x, z) in enumerate([(-24, 96), (-8, 104), (14, 92), (30, 110)])]
    return scene(
        "casters_behind",
        "Tall towers behind the camera whose shadows fall forward into the view; light from behind.",
        camera((0, 3, 70), from_angles(0, -3), far=200),
        {"type": "directional", "direction": travelling(195, 25)},
        small_town(rng, 50) + towers, 260)


def light_overhead(rng):
    return scene(
        "light_overhead",
        "Light straight down, perpendicular to a horizontal view direction.",
        camera((0, 2.5, 70), from_angles(0, 0), far=200),
        {"type": "directional", "direction": [0, -1, 0]},
        small_town(rng), 160)


def far_near_1e5(rng):
    posts = [{"type": "box", "name": "post_%d" % i, "position": vec(side * 0.6, 1.1, -z),
              "size": [0.05, 2.2, 0.05]}
             for i, (side, z) in enumerate([(1, 0.3), (-1, 0.8), (1, 1.5), (-1, 2.5), (1, 4)])]
    mote = {"type": "sphere", "name": "mote", "position": [0.05, 1.68, -0.1], "radius": 0.01}
    far = town(rng, 55, 960, near_street(0, 20), lot=60)
    return scene(
        "far_near_1e5", "far / near = 1e5: posts and a mote within reach, a town up to 1 km away.",
        camera((0, 1.7, 0), from_angles(2, -2), near=0.01, far=1000),
        {"type": "directional", "direction": travelling(50, 20)},
        posts + [mote] + far, 2000)


def box_on_plane(rng):
    return {"name": "box_on_plane", "description": "One box on a plane, light almost overhead.",
            "camera": camera((0, 4, 8), (0, -0.35, -1), near=0.1, far=50),
            "light": {"type": "directional", "direction": vec(0.2, -1, -0.1)},
            "objects": [ground(20), {"type": "box", "name": "box", "position": [0, 1, 0],
                                     "size": [2, 2, 2]}]}


def planks_on_plane(rng):
    return {"name": "planks_on_plane",
            "description": "A box and low planks on a plane, a low sun behind them: shadows a large normal offset "
                           "lifts off their casters (contact shadows restore them).",
            "camera": camera((0, 4, 8), (0, -0.35, -1), near=0.1, far=50),
            "light": {"type": "directional", "direction": travelling(25, 30)},
            "objects": [ground(20),
                        {"type": "box", "name": "box", "position": [0, 1, 0], "size": [2, 2, 2]},
                        {"type": "box", "name": "plank", "position": [-3, 0.1, 1], "size": [2, 0.2, 0.5]},
                        {"type": "box", "name": "slab", "position": [3, 0.15, 0.5], "size": [1.5, 0.3, 1]},
                        {"type": "box", "name": "curb", "position": [0, 0.1, 3], "size": [8, 0.2, 0.3]}]}


def few_objects(rng):
    objects = [house(rng, -6, -4), tower(rng, 6, -6, 8, 12), tank(rng, 5, 5)] + tree(rng, -5, 6)
    return objects + [{"type": "sphere", "name": "ball", "position": [0, 1, 0], "radius": 1}]


def spot(rng):
    return scene(
        "spot", "A spot light over a few objects.",
        camera((0, 10, 28), from_angles(0, -20), near=0.1, far=100),
        {"type": "spot", "position": [4, 16, 8], "direction": vec(-0.25, -1, -0.5),
         "cone_deg": 70},
        few_objects(rng), 60)


def point(rng):
    mesh = {"type": "mesh", "name": "tetrahedron", "file": "../meshes/tetrahedron.obj",
            "position": [0, 0, -10], "rotation": [0, 30, 0], "scale": 3}
    return scene(
        "point", "A point light above a few objects (one a mesh).",
        camera((0, 10, 28), from_angles(0, -20), near=0.1, far=100),
        {"type": "point", "position": [0, 9, 0]},
        few_objects(rng) + [mesh], 60)


def volumes(rng):
    """Closed meshes only (boxes, spheres, a cylinder, a mesh) for shadow volumes; a point light,
    so that the volumes have back caps at infinity."""
    objects = [
        {"type": "box", "name": "crate", "position": [-4, 1, 0], "rotation": [0, 20, 0], "size": [2, 2, 2]},
        {"type": "box", "name": "pillar", "position": [5, 2.5, -4], "rotation": [0, -35, 0], "size": [1.2, 5, 1.2]},
        {"type": "sphere", "name": "ball", "position": [2.5, 1.2, 1], "radius": 1.2},
        {"type": "sphere", "name": "floating_ball", "position": [-1, 3.5, 3], "radius": 0.7},
        {"type": "cylinder", "name": "drum", "position": [-5, 1, -6], "radius": 1, "height": 2},
        {"type": "mesh", "name": "tetrahedron", "file": "../meshes/tetrahedron.obj",
         "position": [0, 0, -4], "rotation": [0, 30, 0], "scale": 3}]
    return scene(
        "volumes", "Closed meshes on a ground plane under a point light, for shadow volumes.",
        camera((0, 7, 16), (0, -0.4, -1), near=0.1, far=100),
        {"type": "point", "position": [-7, 12, -8]},
        objects, 40)


def volumes_eye_in_shadow(rng):
    """The camera stands in the shadow of a tower behind it: z-pass counts from inside a volume."""
    objects = [
        {"type": "box", "name": "tower", "position": [0, 5, 10], "size": [8, 10, 2]},
        {"type": "box", "name": "crate", "position": [-2, 1, -6], "rotation": [0, 25, 0], "size": [2, 2, 2]},
        {"type": "sphere", "name": "ball", "position": [3, 1, -16], "radius": 1}]
    return scene(
        "volumes_eye_in_shadow", "The camera inside a tower's shadow volume (low sun behind the tower).",
        camera((0, 1.7, 6), (0, -0.15, -1), near=0.1, far=100),
        {"type": "directional", "direction": vec(0.1, -0.5, -1)},
        objects, 60)


def lamp_room(rng):
    """A bare bulb in a 10 x 3 x 10 room: furniture below it, beside it on every side and a beam
    above it, so that every direction from the light holds a caster (omnidirectional maps: dpsm,
    cube). Long straight edges near the light show how a paraboloid bends them."""
    def box(name, position, size, rotation=0):
        return {"type": "box", "name": name, "position": vec(*position), "rotation": vec(0, rotation, 0),
                "size": vec(*size)}

    def wall(name, position, size):
        return {**box(name, position, size), "casts": False}

    objects = [
        wall("ceiling", (0, 3.05, 0), (10, 0.1, 10)),
        wall("wall_west", (-5.05, 1.5, 0), (0.1, 3, 10)),
        wall("wall_east", (5.05, 1.5, 0), (0.1, 3, 10)),
        wall("wall_north", (0, 1.5, -5.05), (10, 3, 0.1)),
        wall("wall_south", (0, 1.5, 5.05), (10, 3, 0.1)),
        box("table", (0.4, 0.72, 0.3), (2.2, 0.08, 1.2), 15),
        box("table_leg_1", (-0.5, 0.34, -0.1), (0.08, 0.68, 0.08), 15),
        box("table_leg_2", (1.3, 0.34, 0.7), (0.08, 0.68, 0.08), 15),
        box("shelf", (-4.3, 1.1, -0.5), (0.6, 2.2, 2.4)),
        box("cabinet", (3.6, 0.6, -1.8), (1.2, 1.2, 0.6), -20),
        box("chair_seat", (-0.9, 0.45, 1.4), (0.5, 0.06, 0.5), 30),
        box("chair_back", (-1.1, 0.8, 1.6), (0.5, 0.7, 0.06), 30),
        box("beam", (0, 2.7, 0), (9.8, 0.2, 0.25)),
        box("pillar", (1.8, 1.5, -3.2), (0.4, 3, 0.4)),
        {"type": "sphere", "name": "globe", "position": vec(2.6, 1.7, 1.6), "radius": 0.3},
        {"type": "cylinder", "name": "vase", "position": vec(-0.2, 0.96, 0.5), "radius": 0.1, "height": 0.4},
    ]
    return scene(
        "lamp_room", "A bare bulb in a room: casters on every side of a point light (dpsm, cube).",
        camera((4.4, 2.4, 4.4), (-0.62, -0.33, -0.71), fov=70, near=0.05, far=20),
        {"type": "point", "position": [0, 2.1, 0], "range": [0.05, 12]},
        objects, 10)


def soft_shadows(rng):
    return {"name": "soft_shadows",
            "description": "A post and a raised slab under a sun 2 degrees wide: each shadow sharp where it "
                           "meets its caster and soft away from it (contact hardening: what PCSS reproduces "
                           "and a fixed PCF kernel does not).",
            "camera": camera((-0.5, 3, 3.5), (-0.1, -0.6, -1), near=0.1, far=50),
            "light": {"type": "directional", "direction": travelling(60, 40), "angular_radius_deg": 2},
            "objects": [ground(20),
                        {"type": "box", "name": "post", "position": [-2.5, 1.5, -1], "size": [0.3, 3, 0.3]},
                        {"type": "box", "name": "slab", "position": [1.5, 1.6, -1], "size": [2, 0.15, 2]},
                        {"type": "box", "name": "leg", "position": [1.5, 0.8, -1], "size": [0.2, 1.6, 0.2]}]}


SCENES = [default, light_parallel_behind, light_parallel_front, casters_behind, light_overhead,
          far_near_1e5, box_on_plane, spot, point, volumes, volumes_eye_in_shadow, lamp_room,
          grazing_sun, sun_disc, soft_shadows, overhead_view, planks_on_plane]


def seed_of(make):
    """Each scene's random seed: its place in SCENES, from 1."""
    return SCENES.index(make) + 1


def write(data, path):
    """One line per object keeps the files short and diffable."""
    head = {k: v for k, v in data.items() if k != "objects"}
    lines = ["{"] + ["  %s: %s," % (json.dumps(k), json.dumps(v)) for k, v in head.items()]
    lines.append('  "objects": [')
    lines += ["    %s," % json.dumps(o) for o in data["objects"]]
    lines[-1] = lines[-1].rstrip(",")
    lines += ["  ]", "}"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    for make in SCENES:
        write(make(random.Random(seed_of(make))), os.path.join(HERE, make.__name__ + ".json"))


if __name__ == "__main__":
    main()
