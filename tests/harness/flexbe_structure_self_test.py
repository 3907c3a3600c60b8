"""Self-test of flexbe_structure.py: deliberately broken behaviors (and correct ones with
embedded behaviors, ROS 1 and ROS 2, and a ConcurrencyContainer), each of which must give
exactly the expected error, or none.

  flexbe_structure.py --self-test
"""
import flexbe_structure

HEADER = {
    1: "from flexbe_core import Behavior, Autonomy, OperatableStateMachine, "
       "ConcurrencyContainer, PriorityContainer, Logger\n",
    2: "from flexbe_core import Autonomy\nfrom flexbe_core import Behavior\n"
       "from flexbe_core import ConcurrencyContainer\nfrom flexbe_core import Logger\n"
       "from flexbe_core import OperatableStateMachine\nfrom flexbe_core import PriorityContainer\n"
       "from flexbe_core import initialize_flexbe_core\n",
}
STATES = '''from flexbe_core import EventState


class KeyState(EventState):
    def __init__(self):
        super(KeyState, self).__init__(outcomes=['ok', 'bad'], input_keys=['x'], output_keys=['y'])
'''


def behavior_module(cls, init, create, imports="", ros=2):
    """A behavior module in the generated shape; init and create are indented statements."""
    node = ", node" if ros == 2 else ""
    ros_init = ("        self.node = node\n        initialize_flexbe_core(node)\n"
                if ros == 2 else "")
    return (HEADER[ros] + "from flexbe_states.wait_state import WaitState\n"
            "from flexbe_states.log_state import LogState\n"
            "from sm_flexbe_behaviors.sm_states import KeyState\n" + imports +
            f"\n\nclass {cls}(Behavior):\n    def __init__(self{node}):\n"
            f"        super({cls}, self).__init__()\n        self.name = '{cls}'\n" + ros_init +
            "".join("        " + line + "\n" for line in init) +
            "\n    def create(self):\n" +
            "".join("        " + line + "\n" for line in create) +
            "        return _state_machine\n")


def wait(label, target="finished", extra=None):
    """A WaitState add line; `extra` the remapping's entries (None: no remapping argument)."""
    remapping = "" if extra is None else f", remapping={{{extra}}}"
    return (f"OperatableStateMachine.add('{label}', WaitState(wait_time=1), "
            f"transitions={{'done': '{target}'}}, autonomy={{'done': Autonomy.Off}}{remapping})")


ROOT = "_state_machine = OperatableStateMachine(outcomes=['finished', 'failed'])"
PICK = "from sm_flexbe_behaviors.pick_block_sm import PickBlockSM\n"


def pick_block(ros):
    return behavior_module("PickBlockSM", ["self.add_parameter('speed', 0.5)"], [
        "_state_machine = OperatableStateMachine(outcomes=['finished', 'failed'], "
        "input_keys=['x'], output_keys=['y'])",
        "with _state_machine:",
        "    OperatableStateMachine.add('KEY', KeyState(), transitions={'ok': 'WAIT', "
        "'bad': 'failed'}, autonomy={'ok': Autonomy.Off, 'bad': Autonomy.High}, "
        "remapping={'x': 'x', 'y': 'y'})",
        "    OperatableStateMachine.add('WAIT', WaitState(wait_time=self.speed), "
        "transitions={'done': 'finished'}, autonomy={'done': Autonomy.Off})"],
        ros=ros)


def main_with_pick(ros, init=None, use=None, extra_create=()):
    node = ", node" if ros == 2 else ""
    init = init if init is not None else [f"self.add_behavior(PickBlockSM, 'PICK_BLOCK'{node})"]
    use = use or "self.use_behavior(PickBlockSM, 'PICK_BLOCK', parameters={'speed': 0.1})"
    return behavior_module("MainSM", init, [
        ROOT, "with _state_machine:",
        f"    OperatableStateMachine.add('PICK_BLOCK', {use}, transitions={{'finished': "
        "'finished', 'failed': 'failed'}, autonomy={'finished': Autonomy.Off, 'failed': "
        "Autonomy.Off}, remapping={'x': 'a', 'y': 'b'})", *extra_create], imports=PICK, ros=ros)


def case_files(sm_files, manifest_class="MainSM", manifest_module="sm_sm"):
    files = {"sm_manifest.py": f"manifest = {{'executable': {{'package_path': "
                               f"'sm_flexbe_behaviors.{manifest_module}', "
                               f"'class': '{manifest_class}'}}}}\n",
             "sm_states.py": STATES}
    files.update(sm_files)
    return files


def simple(create, init=(), ros=2):
    """A one-module case whose create() is ROOT + the given lines."""
    return case_files({"sm_sm.py": behavior_module("MainSM", list(init), [ROOT] + create, ros=ros)})


SELF_TESTS = {  # case: (files, expected error text or None when it must pass)
    "good_ros2_embedded": (case_files({"sm_sm.py": main_with_pick(2),
                                       "pick_block_sm.py": pick_block(2)}), None),
    "good_ros1_embedded": (case_files({"sm_sm.py": main_with_pick(1),
                                       "pick_block_sm.py": pick_block(1)}), None),
    "good_concurrency": (simple([
        "_sm_con = ConcurrencyContainer(outcomes=['done', 'failed'], conditions=[('done', "
        "[('A', 'done'), ('B', 'done')]), ('failed', [('K', 'bad')])])",
        "with _sm_con:", "    " + wait("A", "done"), "    " + wait("B", "done"),
        "    OperatableStateMachine.add('K', KeyState(), transitions={'ok': 'done', 'bad': "
        "'failed'}, autonomy={'ok': Autonomy.Off, 'bad': Autonomy.Off}, remapping={'x': 'x'})",
        "with _state_machine:",
        "    OperatableStateMachine.add('CON', _sm_con, transitions={'done': 'finished', "
        "'failed': 'failed'}, autonomy={'done': Autonomy.Off, 'failed': Autonomy.Off})"]),
        None),
    "unconnected_outcome": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('K', KeyState(), transitions={'ok': 'finished'}, "
        "autonomy={'ok': Autonomy.Off, 'bad': Autonomy.Off})"]),
        "outcome 'bad' has no transition"),
    "missing_target": (simple(["with _state_machine:", "    " + wait("A", "NOWHERE")]),
                       "goes to 'NOWHERE'"),
    "use_without_add": (case_files({"sm_sm.py": main_with_pick(2, init=[]),
                                    "pick_block_sm.py": pick_block(2)}),
                        "was not added with add_behavior"),
    "undeclared_parameter": (case_files({
        "sm_sm.py": main_with_pick(2, use="self.use_behavior(PickBlockSM, 'PICK_BLOCK', "
                                          "parameters={'velocity': 0.1})"),
        "pick_block_sm.py": pick_block(2)}), "'velocity' is not a parameter of PickBlockSM"),
    "empty_remapping": (simple(["with _state_machine:", "    " + wait("A", extra="")]),
                        "remapping={} is written out"),
    "bad_remapping_key": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('K', KeyState(), transitions={'ok': 'finished', 'bad': "
        "'failed'}, autonomy={'ok': Autonomy.Off, 'bad': Autonomy.Off}, remapping={'z': 'z'})"]),
        "remapping of 'z', which is none of its keys"),
    "added_not_used": (case_files({
        "sm_sm.py": main_with_pick(2, init=["self.add_behavior(PickBlockSM, 'PICK_BLOCK', node)",
                                            "self.add_behavior(PickBlockSM, 'OTHER', node)"]),
        "pick_block_sm.py": pick_block(2)}), "added behaviors never used: OTHER"),
    "added_twice": (case_files({
        "sm_sm.py": main_with_pick(2, init=["self.add_behavior(PickBlockSM, 'PICK_BLOCK', "
                                            "node)"] * 2),
        "pick_block_sm.py": pick_block(2)}), "the id is already added"),
    "ros1_add_with_node": (case_files({
        "sm_sm.py": main_with_pick(1, init=["self.add_behavior(PickBlockSM, 'PICK_BLOCK', 7)"]),
        "pick_block_sm.py": pick_block(1)}), "the class takes none"),
    "duplicate_label": (simple(["with _state_machine:", "    " + wait("A"), "    " + wait("A")]),
                        "state 'A' is added twice"),
    "add_outside_with": (simple([wait("A")]), "outside a `with <container>:` block"),
    "empty_container": (simple(["_sm_x = OperatableStateMachine(outcomes=['done'])",
                                "with _sm_x:", "    pass", "with _state_machine:",
                                "    " + wait("A")]), "has no states"),
    "autonomy_not_a_level": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('A', WaitState(wait_time=1), transitions={'done': "
        "'finished'}, autonomy={'done': 0})"]), "not an Autonomy level"),
    "autonomy_unknown_outcome": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('A', WaitState(wait_time=1), transitions={'done': "
        "'finished'}, autonomy={'done': Autonomy.Off, 'fail': Autonomy.Off})"]),
        "outcome 'fail' has no transition"),
    "concurrency_bad_condition": (simple([
        "_sm_con = ConcurrencyContainer(outcomes=['done'], conditions=[('done', [('A', 'done'), "
        "('Z', 'done')]), ('other', [('A', 'nope')])])",
        "with _sm_con:", "    " + wait("A", "done"),
        "with _state_machine:",
        "    OperatableStateMachine.add('CON', _sm_con, transitions={'done': 'finished'}, "
        "autonomy={'done': Autonomy.Off})"]),
        "names 'Z', which is not one of its states"),
    "concurrency_sibling_target": (simple([
        "_sm_con = ConcurrencyContainer(outcomes=['done'], conditions=[('done', [('B', 'done')])])",
        "with _sm_con:", "    " + wait("A", "B"), "    " + wait("B", "done"),
        "with _state_machine:",
        "    OperatableStateMachine.add('CON', _sm_con, transitions={'done': 'finished'}, "
        "autonomy={'done': Autonomy.Off})"]),
        "one of the concurrency container's outcomes"),
    "missing_self_parameter": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('A', WaitState(wait_time=self.speed), transitions="
        "{'done': 'finished'}, autonomy={'done': Autonomy.Off})"]),
        "create() reads self.speed, which __init__ does not define"),
    "bad_log_severity": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('L', LogState(text='x', severity='loud'), transitions="
        "{'done': 'finished'}, autonomy={'done': Autonomy.Off})"]),
        "is not a Logger.REPORT_* level"),
    "manifest_wrong_class": (dict(simple(["with _state_machine:", "    " + wait("A")]),
                                  **{"sm_manifest.py": "manifest = {'executable': {'package_path':"
                                     " 'sm_flexbe_behaviors.sm_sm', 'class': 'OtherSM'}}\n"}),
                             "defines no class OtherSM"),
}


def run():
    failures = []
    for case, (files, expected) in SELF_TESTS.items():
        errors = flexbe_structure.CaseCheck(files).check()
        if expected is None and errors:
            failures.append(f"{case} must pass: {errors}")
        elif expected is not None and not any(expected in e for e in errors):
            failures.append(f"{case}: expected an error with {expected!r}, got {errors}")
    for failure in failures:
        print("FAIL " + failure)
    broken = sum(1 for _, expected in SELF_TESTS.values() if expected is not None)
    print(f"self-test: {len(SELF_TESTS)} cases ({broken} broken): {len(failures)} failures")
    return 1 if failures else 0
