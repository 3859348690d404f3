"""The serial sweep's record of the stacks after its last segment."""

from kittools.link.serial_points import Outcome, last_stacks


def test_last_stacks_takes_the_last_run_of_stack_lines():
    console = ["KIT STACK name=a size=8 used=1", "KIT STACK name=b size=8 used=2", "KIT SWEEP axis=uplink",
               "KIT STACK name=a size=8 used=3", "KIT STACK name=b size=8 used=4", "KIT SWEEP axis=uplink"]
    assert last_stacks(console) == ["KIT STACK name=a size=8 used=3", "KIT STACK name=b size=8 used=4"]
    assert last_stacks(console[:2]) == console[:2]
    assert last_stacks(["KIT BANNER"]) == []


def test_the_stacks_stay_out_of_the_records_lines():
    outcome = Outcome(lines=["KIT SWEEP axis=uplink"], stacks=["KIT STACK name=a size=8 used=3"])
    data = outcome.to_json()
    assert data["stacks"] == ["KIT STACK name=a size=8 used=3"]
    assert all("STACK" not in line for line in data["lines"])
