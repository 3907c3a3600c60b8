#!/usr/bin/env python

import smach
import random


class RandomOutcomeState(smach.State):
    """Runs its callbacks, then ends with one of its outcomes chosen at random."""

    def __init__(self, input_keys=[], output_keys=['outcome'], callbacks=[], outcomes=['succeeded']):
        if 'outcome' not in output_keys:
            output_keys = list(output_keys) + ['outcome']
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._choices = sorted(outcomes)
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        outcome = random.choice(self._choices)
        userdata.outcome = outcome
        return outcome

class CallbacksState(smach.State):
    """Runs its callbacks on the userdata, then succeeds."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        return 'succeeded'


@smach.cb_interface(input_keys=[],
                    output_keys=['outcome'],
                    outcomes=['foo_0', 'foo_1', 'foo_2'])
def outcome_randomize_2b9e2e855b1e4d2d8f1bcf5d11c61f63_lambda_cb(userdata):
    lambda_cb = lambda ud: random.choice(['foo_0', 'foo_1', 'foo_2'])
    userdata.outcome = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=[],
                    output_keys=['outcome'],
                    outcomes=[])
def outcome_foo_0_89e0a3d656534c69bf16475ba8e7f09c_lambda_cb(userdata):
    lambda_cb = lambda ud: random.choice(['foo_0', 'foo_1', 'foo_2'])
    userdata.outcome = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=[],
                    output_keys=['outcome'],
                    outcomes=[])
def outcome_foo_1_688fcb88b3584bedb6f4d82e02f646e2_lambda_cb(userdata):
    lambda_cb = lambda ud: random.choice(['foo_0', 'foo_1', 'foo_2'])
    userdata.outcome = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=[],
                    output_keys=['outcome'],
                    outcomes=[])
def outcome_foo_2_4a5b0c96716c412aa819f7af3c0e5df8_lambda_cb(userdata):
    lambda_cb = lambda ud: random.choice(['foo_0', 'foo_1', 'foo_2'])
    userdata.outcome = lambda_cb(userdata)
    return 'succeeded'


def main():
    rnd = smach.StateMachine(outcomes=['final_outcome'])

    with rnd:
        smach.StateMachine.add('RANDOMIZE',
                               RandomOutcomeState(callbacks = ['outcome_randomize_2b9e2e855b1e4d2d8f1bcf5d11c61f63_lambda_cb'], outcomes=['foo_0', 'foo_1', 'foo_2']),
                               transitions={'foo_0':'FOO_0',
                                            'foo_1':'FOO_1',
                                            'foo_2':'FOO_2'})

        smach.StateMachine.add('FOO_0',
                               CallbacksState(callbacks = ['outcome_foo_0_89e0a3d656534c69bf16475ba8e7f09c_lambda_cb']),
                               transitions={'succeeded':'RANDOMIZE'})

        smach.StateMachine.add('FOO_1',
                               CallbacksState(callbacks = ['outcome_foo_1_688fcb88b3584bedb6f4d82e02f646e2_lambda_cb']),
                               transitions={'succeeded':'RANDOMIZE'})

        smach.StateMachine.add('FOO_2',
                               CallbacksState(callbacks = ['outcome_foo_2_4a5b0c96716c412aa819f7af3c0e5df8_lambda_cb']),
                               transitions={'succeeded':'final_outcome'})

    outcome = rnd.execute()


if __name__ == '__main__':
    main()
