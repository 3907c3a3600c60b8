#!/usr/bin/env python

import smach


@smach.cb_interface(input_keys=['animals'], output_keys=['animals'], outcomes=['succeeded'])
def foo_animals_cb(userdata):
    userdata['animals'].append('turtles')
    return 'succeeded'


class Foo(smach.State):
    def __init__(self, name, input_keys=[], output_keys=[], callbacks=[]):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded'])
        self._name = name
        
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


@smach.cb_interface(input_keys=['animals'],
                    output_keys=['animals'],
                    outcomes=[])
def animals_foo_1_9ffd7fc1ba6147e4b0d558fa371f9bdc_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.animals if ud.animals.append("ducks") else ud.animals
    userdata.animals = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['animals', 'numbers'],
                    output_keys=['numbers'],
                    outcomes=[])
def numbers_foo_2_6cd155d3de3645de8332ea61218c2f57_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.numbers if ud.numbers.append(42) else ud.numbers
    userdata.numbers = lambda_cb(userdata)
    return 'succeeded'


def main():
    sm = smach.StateMachine(outcomes=['final_outcome'])
    sm.userdata.animals = ['cats', 'dogs', 'sharks']
    sm.userdata.numbers = [1, 2, 3]


    with sm:
        smach.StateMachine.add('FOO_0', Foo('FOO_0', input_keys = ['animals'], output_keys = ['animals'], callbacks = ['foo_animals_cb']),
                               transitions={'succeeded':'FOO_1'})

        smach.StateMachine.add('FOO_1',
                               CallbacksState(input_keys = ['animals'], output_keys = ['animals'], callbacks = ['animals_foo_1_9ffd7fc1ba6147e4b0d558fa371f9bdc_lambda_cb']),
                               transitions={'succeeded':'FOO_2'})

        smach.StateMachine.add('FOO_2', Foo('FOO_2', input_keys = ['animals', 'numbers'], output_keys = ['animals', 'numbers'], callbacks = ['foo_animals_cb', 'numbers_foo_2_6cd155d3de3645de8332ea61218c2f57_lambda_cb']),
                               transitions={'succeeded':'final_outcome'})

    outcome = sm.execute()


if __name__ == '__main__':
    main()
