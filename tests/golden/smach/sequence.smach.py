#!/usr/bin/env python

import smach
import random


class PrintUserdataState(smach.State):
    """Logs every input key with its value, in the order given, then succeeds."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._keys = list(dict.fromkeys(input_keys))  # in order (SMACH keeps a set)

    def execute(self, userdata):
        for key in self._keys:
            smach.loginfo('userdata.{}: {}'.format(key, userdata[key]))
        return 'succeeded'

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


@smach.cb_interface(input_keys=['counter'],
                    output_keys=['counter'],
                    outcomes=['succeeded'])
def counter_count_041534adeeb54da28f35f58ba0ef566b_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.counter + 1
    userdata.counter = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=[],
                    output_keys=['outcome'],
                    outcomes=['heads', 'tails'])
def outcome_choose_eb79e3aa21bd4de0a126e4e123215be4_lambda_cb(userdata):
    lambda_cb = lambda ud: random.choice(['heads', 'tails'])
    userdata.outcome = lambda_cb(userdata)
    return 'succeeded'


def main():
    sequence = smach.StateMachine(outcomes=['done', 'failed'])
    sequence.userdata.counter = 0
    sequence.userdata.greeting = 'hello'


    with sequence:
        smach.StateMachine.add('SAY_HELLO',
                               PrintUserdataState(input_keys = ['greeting']),
                               transitions={'succeeded':'COUNT'})

        smach.StateMachine.add('COUNT',
                               CallbacksState(input_keys = ['counter'], output_keys = ['counter'], callbacks = ['counter_count_041534adeeb54da28f35f58ba0ef566b_lambda_cb'], outcomes=['succeeded']),
                               transitions={'succeeded':'SAY_AGAIN'})

        smach.StateMachine.add('SAY_AGAIN',
                               PrintUserdataState(input_keys = ['greeting', 'counter']),
                               transitions={'succeeded':'CHOOSE'})

        smach.StateMachine.add('CHOOSE',
                               RandomOutcomeState(callbacks = ['outcome_choose_eb79e3aa21bd4de0a126e4e123215be4_lambda_cb'], outcomes=['heads', 'tails']),
                               transitions={'heads':'done',
                                            'tails':'failed'})

    outcome = sequence.execute()


if __name__ == '__main__':
    main()
