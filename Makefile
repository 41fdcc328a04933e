# HAVEN for ROS 2. `make demo` sets everything up and runs the main job (one recorded hallway trial);
# `make test` runs every test; `make docs` builds the documentation site.
.PHONY: setup demo docs test test-core test-unit test-integration test-ros test-browser coverage bench lock clean

setup:
	@./scripts/setup.sh

demo:  # (the setup the demo needs: no Nav2 messages, no browser; `make setup` adds them)
	@HAVEN_SETUP_FOR=demo ./scripts/setup.sh
	.venv/bin/haven run

test: setup
	./scripts/test.sh

# The documentation site: docs/_build/html/index.html (warnings are errors, as in make test).
docs: setup
	.venv/bin/sphinx-build -W --keep-going -q -b html docs docs/_build/html

# One tier at a time (conftest.py says what each holds); `make test` runs them all. test-core: the
# unit tier (the core, no ROS process), on every core.
test-core test-unit: setup
	.venv/bin/pytest -q -n auto -m unit

test-integration: setup
	.venv/bin/pytest -q -n auto --dist loadfile -m "integration and not ros and not browser"

test-ros: setup
	.venv/bin/pytest -q -m "ros and not browser"

test-browser: setup
	.venv/bin/pytest -q -m browser

# Line coverage of the unit and integration tiers, every process they start included (.coveragerc);
# HAVEN_COVERAGE_ALL=1 adds the ros and browser tiers.
coverage: setup
	./scripts/coverage.sh

bench: setup
	.venv/bin/python bench/sim_speed.py
	.venv/bin/python bench/odom_rate.py
	.venv/bin/python bench/planner_latency.py
	.venv/bin/python bench/map_walls.py
	.venv/bin/python bench/trials.py
	.venv/bin/python bench/web_wire.py
	.venv/bin/python bench/web_loop.py
	.venv/bin/python bench/batch_throughput.py --trials 300 --repeat 1 --dask
	.venv/bin/python bench/flood.py --runs 3

lock:
	./scripts/lock.sh

clean:
	rm -rf .venv .venv-noros docs/_build docs/_generated ros2_ws/build ros2_ws/install ros2_ws/log .pytest_cache .mypy_cache
