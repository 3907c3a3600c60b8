#!/usr/bin/env python

import smach


class ParamState(smach.State):
    def __init__(self, name, outcome, label=''):
        smach.State.__init__(self, outcomes=['outcome_a', 'outcome_b'])
        self._name, self._outcome, self._label = name, outcome, label

    def execute(self, userdata):
        smach.loginfo('{} ({}) returns {}'.format(self._name, self._label, self._outcome))
        return self._outcome

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


@smach.cb_interface(input_keys=['x'],
                    output_keys=['y'],
                    outcomes=[])
def y_second_326e44f783da4b9c929d71d4f6888976_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.x * 2
    userdata.y = lambda_cb(userdata)
    return 'succeeded'


def main():
    short = smach.StateMachine(outcomes=['finished'])
    short.userdata.x = 1


    with short:
        smach.StateMachine.add('FIRST',
                               ParamState('ONE', 'outcome_a'),
                               transitions={'outcome_a':'SECOND',
                                            'outcome_b':'finished'})

        smach.StateMachine.add('SECOND',
                               CallbacksState(input_keys = ['x'], output_keys = ['y'], callbacks = ['y_second_326e44f783da4b9c929d71d4f6888976_lambda_cb']),
                               transitions={'succeeded':'finished'},
                               remapping={'x':'x',
                                          'y':'y'})

    outcome = short.execute()


if __name__ == '__main__':
    main()
