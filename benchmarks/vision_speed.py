"""Time of image mode's parts: rendering a photo, detection + grounding per panel, the same
grounding read back from the on-disk cache (a temporary directory), one display reading
(window located once, then a crop per photo), on a sample of bundled appliances.

    python benchmarks/vision_speed.py [--appliances kettle_1,microwave_1] [--reads 10]
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time

import numpy as np

from apbot.bench.suite import load_suite
from apbot.sim.compiled import compiled_model
from apbot.sim.simulator import Simulator
from apbot.vision.cache import cache_dir, cache_key, cached_ground, store
from apbot.vision.ground import ground
from apbot.vision.mode import camera_for
from apbot.vision.reading import DisplayCamera
from apbot.vision.render import PanelScene


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--appliances", default="kettle_1,microwave_1,air_fryer_2,dishwasher_3")
    parser.add_argument("--reads", type=int, default=10)
    args = parser.parse_args()
    suite = load_suite()
    renders, groundings, cached, reads = [], [], [], []
    os.environ["APBOT_CACHE_DIR"] = tempfile.mkdtemp(prefix="apbot-vision-speed-")
    for name in args.appliances.split(","):
        appliance = suite.get(name.strip())
        scene = PanelScene.of(appliance)
        camera = camera_for(appliance.id)
        sim = Simulator(compiled_model(appliance.model))
        seen = sim.reset()
        started = time.perf_counter()
        photo = scene.photograph(seen.display, seen.lamps, camera, 1)
        renders.append(time.perf_counter() - started)
        found = ground(np.asarray(photo.image), list(appliance.model.actions))
        groundings.append(found.seconds)
        folder = cache_dir()
        assert folder is not None
        names = list(appliance.model.actions)
        store(folder / "grounding" / f"{cache_key(np.asarray(photo.image), names)}.json", found)
        started = time.perf_counter()
        cached_ground(np.asarray(photo.image), names)  # the key (hash of the photo) + the load
        cached.append(time.perf_counter() - started)
        reader = DisplayCamera(found.window)
        actions = list(sim.actions)
        for i in range(args.reads):
            name_i = actions[i % len(actions)]
            seen = sim.step(name_i, appliance.model.actions[name_i].seconds)
            photo = scene.photograph(seen.display, seen.lamps, camera, i + 2)
            started = time.perf_counter()
            reader.read(photo.image)
            reads.append(time.perf_counter() - started)
        print(f"{appliance.id}: detection + grounding {found.seconds:.2f} s, "
              f"{len(found.actions)}/{len(appliance.model.actions)} actions grounded")  # fmt: skip
    print(f"render one photo: median {statistics.median(renders):.3f} s")
    print(f"detection + grounding per panel: median {statistics.median(groundings):.2f} s, "
          f"max {max(groundings):.2f} s")  # fmt: skip
    print(f"grounding from the disk cache: median {statistics.median(cached):.3f} s, "
          f"max {max(cached):.3f} s")  # fmt: skip
    print(f"display reading per photo: median {statistics.median(reads):.3f} s, "
          f"max {max(reads):.3f} s ({len(reads)} reads)")  # fmt: skip


if __name__ == "__main__":
    main()
