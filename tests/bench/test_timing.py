# The planning rows' timing helper: the timed call is the second of two, and only it is timed.
import time

from pm2dof.bench.timing import warm_then_time


def test_warm_then_time_times_only_the_second_call_and_returns_its_result():
    calls = []

    def run():
        calls.append(len(calls))
        if len(calls) == 1:
            time.sleep(0.3)          # the untimed warm-up: its cost must not be counted
        return f"call {len(calls)}"

    out, seconds = warm_then_time(run)
    assert calls == [0, 1]
    assert out == "call 2"
    assert 0.0 <= seconds < 0.3
