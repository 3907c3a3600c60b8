"""The SMACHA scripts the comparison generates: the flat scaling script, the counter loop and
the Concurrence fan-out.

flat_script(n) has the shape of bench/passes_bench.cpp's `flat`: one container of n WorkState
leaves in a chain, each reading the key its predecessor writes (keys k0..k7) and `speed`, with
a back edge (`aborted` goes to the previous state). WorkState is the bench template in
bench/compare/templates (for smachac and SMACHA alike).

counter_loop(n) and fan_out(k, m) use only built-in templates and portable `!expr` callbacks,
so one script compiles to `-target=smach` and `-target=cpp`.
"""

KEYS = 8  # the key vocabulary of the flat script: k0 .. k7


def _key(i):
    return "k%d" % (i % KEYS)


def flat_script(states):
    """passes_bench.cpp's flatScript(states), written in Python."""
    lines = ["name: scale", "template: Base", "outcomes: [done, failed]",
             "userdata: {speed: 0.5" + "".join(", %s: 0" % _key(k) for k in range(KEYS)) + "}",
             "states:"]
    for j in range(states):
        succ = "S%d" % (j + 1) if j + 1 < states else "done"
        back = "S%d" % (j - 1) if j > 0 else "failed"
        lines += ["  - S%d:" % j,
                  "      template: WorkState",
                  "      outcomes: [succeeded, aborted]",
                  "      input_keys: [speed, %s]" % _key(j + KEYS - 1),
                  "      output_keys: [%s]" % _key(j),
                  "      transitions: {succeeded: %s, aborted: %s}" % (succ, back)]
    return "\n".join(lines) + "\n"


def counter_loop(iterations):
    """COUNT adds 1 to `counter`, CHECK leaves once it reaches `iterations`: 2 transitions per
    iteration. The final counter is the iteration count."""
    return """name: counter_loop
template: Base
outcomes: [done]
userdata: {counter: 0}
states:
  - COUNT:
      template: CallbacksState
      input_keys: [counter]
      output_keys: [counter]
      callbacks: {counter: !expr 'counter + 1'}
      transitions: {succeeded: CHECK}
  - CHECK:
      template: ConditionalOutcomeState
      params: {limit: %d}
      input_keys: [counter]
      outcomes: [finished, default]
      callbacks: {finished: !expr 'counter >= limit'}
      transitions: {finished: done, default: COUNT}
""" % iterations


def fan_out(children, rounds):
    """A Concurrence FAN of `children` CallbacksStates (each writes a key of its own from
    `rounds`), run `rounds` times: FAN, then COUNT adds 1 to `rounds`, CHECK loops back to FAN
    until it reaches `rounds`."""
    names = ["C%d" % i for i in range(children)]
    condition = ", ".join("%s: succeeded" % n for n in names)
    lines = ["name: fan_out", "template: Base", "outcomes: [done]",
             "userdata: {rounds: 0}", "states:",
             "  - FAN:",
             "      template: Concurrence",
             "      outcomes: [ok]",
             "      default_outcome: ok",
             "      input_keys: [rounds]",
             "      outcome_map: {ok: {%s}}" % condition,
             "      transitions: {ok: COUNT}",
             "      states:"]
    for i, name in enumerate(names):
        lines += ["        - %s:" % name,
                  "            template: CallbacksState",
                  "            input_keys: [rounds]",
                  "            output_keys: [out%d]" % i,
                  "            callbacks: {out%d: !expr 'rounds + %d'}" % (i, i)]
    lines += ["  - COUNT:",
              "      template: CallbacksState",
              "      input_keys: [rounds]",
              "      output_keys: [rounds]",
              "      callbacks: {rounds: !expr 'rounds + 1'}",
              "      transitions: {succeeded: CHECK}",
              "  - CHECK:",
              "      template: ConditionalOutcomeState",
              "      params: {limit: %d}" % rounds,
              "      input_keys: [rounds]",
              "      outcomes: [finished, default]",
              "      callbacks: {finished: !expr 'rounds >= limit'}",
              "      transitions: {finished: done, default: FAN}"]
    return "\n".join(lines) + "\n"
