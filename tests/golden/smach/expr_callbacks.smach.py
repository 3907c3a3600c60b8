#!/usr/bin/env python

import smach
import random


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

class ConditionalOutcomeState(smach.State):
    """Ends with the first outcome whose callback output is true, else `default`."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=[]):
        # Each condition's callback writes the key named like the outcome, which execute()
        # then reads: it is both an output and an input key.
        self._conditions = [o for o in outcomes if o != 'default']
        input_keys = list(input_keys) + [o for o in self._conditions if o not in input_keys]
        output_keys = list(output_keys) + [o for o in self._conditions if o not in output_keys]
        if 'outcome' not in output_keys:
            output_keys.append('outcome')
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=self._conditions + ['default'])
        
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

        for outcome in self._conditions:
            if outcome in userdata and userdata[outcome]:
                userdata.outcome = outcome
                return outcome
        userdata.outcome = 'default'
        return 'default'


@smach.cb_interface(input_keys=['count', 'name', 'sizes'],
                    output_keys=['count'],
                    outcomes=[])
def count_update_aaf9cb1f543a4479ad61387bd9ce63c8_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.count + 3 * 2 - 1
    userdata.count = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['count', 'name', 'sizes'],
                    output_keys=['label'],
                    outcomes=[])
def label_update_aaf9cb1f543a4479ad61387bd9ce63c8_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.name + '-1' if len(ud.name) > 3 else 'anonymous'
    userdata.label = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['count', 'name', 'sizes'],
                    output_keys=['ratio'],
                    outcomes=[])
def ratio_update_aaf9cb1f543a4479ad61387bd9ce63c8_lambda_cb(userdata):
    lambda_cb = lambda ud: -(ud.count + 7) // 2 % 3 / 4
    userdata.ratio = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['count', 'name', 'sizes'],
                    output_keys=['smallest'],
                    outcomes=[])
def smallest_update_aaf9cb1f543a4479ad61387bd9ce63c8_lambda_cb(userdata):
    lambda_cb = lambda ud: min(ud.sizes) or abs(-1.5)
    userdata.smallest = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['count'],
                    output_keys=['count'],
                    outcomes=['drawn'])
def count_draw_ff8aaa56839946d29d7e1cc35a8e0ac8_lambda_cb(userdata):
    lambda_cb = lambda ud: max(ud.count, 10)
    userdata.count = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['count', 'label'],
                    output_keys=['reached'],
                    outcomes=['reached', 'default'])
def reached_check_a2815d5ea727409ebc438e3f3efe1516_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.count >= 10 and not ud.label == ''
    userdata.reached = lambda_cb(userdata)
    return 'succeeded'


def main():
    expr_callbacks = smach.StateMachine(outcomes=['done', 'failed'])
    expr_callbacks.userdata.count = 0
    expr_callbacks.userdata.name = 'robot'
    expr_callbacks.userdata.sizes = [0.5, 2, 1.25]


    with expr_callbacks:
        smach.StateMachine.add('UPDATE',
                               CallbacksState(input_keys = ['count', 'name', 'sizes'], output_keys = ['count', 'label', 'ratio', 'smallest'], callbacks = ['count_update_aaf9cb1f543a4479ad61387bd9ce63c8_lambda_cb', 'label_update_aaf9cb1f543a4479ad61387bd9ce63c8_lambda_cb', 'ratio_update_aaf9cb1f543a4479ad61387bd9ce63c8_lambda_cb', 'smallest_update_aaf9cb1f543a4479ad61387bd9ce63c8_lambda_cb']),
                               transitions={'succeeded':'DRAW'})

        smach.StateMachine.add('DRAW',
                               RandomOutcomeState(input_keys = ['count'], callbacks = ['count_draw_ff8aaa56839946d29d7e1cc35a8e0ac8_lambda_cb'], outcomes=['drawn']),
                               transitions={'drawn':'CHECK'})

        smach.StateMachine.add('CHECK',
                               ConditionalOutcomeState(input_keys = ['count', 'label'], callbacks = ['reached_check_a2815d5ea727409ebc438e3f3efe1516_lambda_cb'], outcomes=['reached', 'default']),
                               transitions={'default':'failed',
                                            'reached':'done'})

    outcome = expr_callbacks.execute()


if __name__ == '__main__':
    main()
