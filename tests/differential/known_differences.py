"""Where a target legitimately behaves differently from SMACH, with the rule and the script
(tests/differential/cases/) that shows it. The differential test requires each listed case to
differ exactly as recorded here: a change in either runtime shows up as a failure.
"""


class Known:
    def __init__(self, rule, differences):
        self.rule = rule
        self.differences = differences

    def expected(self, _reference):
        return self.differences


RULES = {}

# The SMACH output keeps SMACHA's behaviour where C++ (and FlexBE) differ; `smachac lint`
# warns on scripts that depend on it (stdlib/runtime/README.md, "SMACH output and C++").
MUTABLE = ("values are shared Python objects in SMACH, copies in C++: an in-place change "
           "reaches the parent only in SMACH")
LOWERCASE = "the SMACH output lower-cases userdata keys (smach-lowercased-userdata-key)"
STRING_CODE = ("the SMACH output writes number-like strings as code (smach-string-as-code)")
LEAK = ("a RandomOutcomeState's default callbacks leak to later states in the SMACH output "
        "(smach-leaked-callbacks)")
MAP_ORDER = "maps keep the script's key order in Python, C++ sorts them (smach-map-order)"
RULES.update({
    ("cases/mutable_list", "cpp"): Known(MUTABLE, [
        "userdata: smach {'count': 3, 'items': [1, 2, 3]}, this {'count': 3, 'items': [1, 2]}"]),
    ("cases/lowercased_userdata_key", "cpp"): Known(LOWERCASE, [
        "userdata: smach {'speed': 2}, this {'Speed': 2}"]),
    ("cases/lowercased_userdata_key", "flexbe"): Known(LOWERCASE, [
        "userdata: smach {'speed': 2}, this {'Speed': 2}"]),
    ("golden/smach/userdata_levels", "cpp"): Known(LOWERCASE, [
        "userdata: smach {'first': 'one', 'root_a': 1, 'root_b': 2}, this {'Root_A': 1, "
        "'first': 'one', 'root_b': 2}"]),
    ("golden/smach/userdata_levels", "flexbe"): Known(LOWERCASE, [
        "userdata: smach {'first': 'one', 'root_a': 1, 'root_b': 2}, this {'Root_A': 1, "
        "'first': 'one', 'root_b': 2}"]),
    ("cases/string_as_code", "cpp"): Known(STRING_CODE, [
        "userdata: smach {'count': 42, 'label': '7'}, this {'count': '42', 'label': '7'}"]),
    ("cases/string_as_code", "flexbe"): Known(STRING_CODE, [
        "userdata: smach {'count': 42, 'label': '7'}, this {'count': '42', 'label': '7'}"]),
    ("cases/leaked_random_callbacks", "cpp"): Known(LEAK, [
        "userdata: smach {'leaked': 'go', 'outcome': 'go'}, this {'leaked': 'none', "
        "'outcome': 'go'}"]),
    ("cases/map_order", "cpp"): Known(MAP_ORDER, [
        "userdata: smach {'first': 'z', 'pose': {'a': 2, 'z': 1}}, this {'first': 'a', "
        "'pose': {'a': 2, 'z': 1}}"]),
})

# FlexBE's ConcurrencyContainer checks its conditions after every tick and leaves as soon as
# one holds; SMACH (and the C++ runtime, early_exit off) wait for every child first.
EARLY_EXIT = ("FlexBE ends a ConcurrencyContainer as soon as a condition holds, without "
              "waiting for the children still running")
RULES[("cases/concurrence_ends_early", "flexbe")] = Known(EARLY_EXIT, [
    "states: smach ['PAR -> early', 'PAR/FAST -> done', 'PAR/SLOW -> finished', "
    "'PAR/SLOW/STEP_1 -> succeeded', 'PAR/SLOW/STEP_2 -> succeeded', "
    "'PAR/SLOW/STEP_3 -> succeeded'], this ['PAR -> early', 'PAR/FAST -> done', "
    "'PAR/SLOW -> (no outcome)', 'PAR/SLOW/STEP_1 -> succeeded']"])

# FlexBE's preempt command sets one flag for the whole behavior: from then on every state
# returns `preempted` and every container leaves by it. SMACH 2.5 (and the C++ runtime) pass
# the request to the running state, follow the outcome it returns, and pass a request it
# ignored on to the next state (stdlib/runtime/README.md, "Preemption").
PREEMPT = ("FlexBE ends the whole behavior `preempted` once preempted; SMACH follows the "
           "outcome of the state that serviced the request")
RULES.update({
    ("cases/preempt_serviced", "flexbe"): Known(PREEMPT, [
        "states: smach ['SLEEP -> preempted', 'RECOVER -> succeeded'], this "
        "['SLEEP -> preempted']",
        "outcome: smach recovered, this preempted"]),
    ("cases/preempt_passed_on", "flexbe"): Known(PREEMPT, [
        "states: smach ['STUBBORN -> succeeded', 'SLEEP -> preempted', 'RECOVER -> succeeded'], "
        "this ['STUBBORN -> preempted']",
        "outcome: smach recovered, this preempted"]),
    ("cases/preempt_concurrence", "flexbe"): Known(PREEMPT, [
        "states: smach ['PAR -> mixed', 'PAR/SLEEP -> preempted', 'PAR/STUBBORN -> succeeded'], "
        "this ['PAR -> preempted', 'PAR/SLEEP -> preempted', 'PAR/STUBBORN -> preempted']",
        "outcome: smach mixed, this preempted"]),
})
