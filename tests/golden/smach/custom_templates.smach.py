#!/usr/bin/env python

import smach
import textwrap


def greet(greeting, who):
    return '{}, {}!'.format(greeting, who)


class Greeter(smach.State):
    def __init__(self, greeting, input_keys=[]):
        smach.State.__init__(self, input_keys=input_keys, outcomes=['succeeded'])
        self._greeting = greeting

    def execute(self, userdata):
        smach.loginfo(textwrap.shorten(greet(self._greeting, userdata.who), 40))
        return 'succeeded'

class PrintUserdataState(smach.State):
    """The user's own version, found before the built-in one."""
    def __init__(self, input_keys=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, outcomes=outcomes)

    def execute(self, userdata):
        for key in self.get_registered_input_keys():
            print(key, userdata[key])
        return 'succeeded'


def main():
    custom = smach.StateMachine(outcomes=['done'])
    custom.userdata.who = 'world'

    with custom:
        smach.StateMachine.add('GREET',
                               Greeter('Hello', input_keys = ['who']),
                               transitions={'succeeded':'PRINT'})

        smach.StateMachine.add('PRINT',
                               PrintUserdataState(input_keys = ['who']),
                               transitions={'succeeded':'done'})

    outcome = custom.execute()


if __name__ == '__main__':
    main()
