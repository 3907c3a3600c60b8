{% block meta %}
name: LoadModelState
description: >
  Loads a model into Gazebo at a pose: the model of that name is deleted
  (/gazebo/delete_model), then spawned from its SDF or URDF file
  (/gazebo/spawn_sdf_model or /gazebo/spawn_urdf_model). Without model_path
  the file comes from baxter_sim_examples/models (table: cafe_table, blockN:
  block). A variable left out is read from the input key of the same name
  (pose; reference_frame when the script remaps it, else world). The frame
  base is Baxter's, baxter::base.
language: Python
framework: SMACH
type: State
tags: [baxter]
includes: []
extends:
- State
variables:
- model_name:
    description: The name of the model in Gazebo (table, block1, block2, ...).
    type: str
- - model_path:
      description: The model's SDF or URDF file (default from baxter_sim_examples).
      type: str
- - pose:
      description: >
        The model's pose in reference_frame, [[x, y, z], [qx, qy, qz, qw]]
        (default: input key pose).
      type: list
- - reference_frame:
      description: world or base (default input key reference_frame, else world).
      type: str
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, from_import %}
{% from "BaxterUtils.tpl.py" import join_definitions, join_imports, import_baxter_state, import_pose_functions, define_baxter_state, define_pose_functions, text_argument, data_argument, render_baxter_state %}
{% extends "State.tpl.py" %}

{% block imports %}
{{- join_imports([import_baxter_state(defined_headers),
                 import_module(defined_headers, 'os'),
                 import_module(defined_headers, 'rospkg'),
                 import_pose_functions(defined_headers),
                 from_import(defined_headers, 'gazebo_msgs.srv', 'DeleteModel'),
                 from_import(defined_headers, 'gazebo_msgs.srv', 'SpawnModel')]) }}
{%- endblock imports %}

{% block class_defs %}
{%- set definitions = [define_baxter_state(defined_headers), define_pose_functions(defined_headers)] %}
{%- if 'class_LoadGazeboModelState' not in defined_headers %}
{%- set definition %}
class LoadGazeboModelState(BaxterState):
    """Spawns a Gazebo model at a pose, replacing any model of the same name."""

    MODEL_FILES = {'table': 'cafe_table/model.sdf', 'block': 'block/model.urdf'}
    FRAMES = {'base': 'baxter::base'}
    SERVICE_TIMEOUT = 5.0  # seconds to wait for Gazebo's services

    def __init__(self, model_name, model_path=None, pose=None, reference_frame='world',
                 input_keys=()):
        BaxterState.__init__(self, dict(model_name=model_name, model_path=model_path, pose=pose,
                                        reference_frame=reference_frame), input_keys)

    def model_file(self, model_name):
        kind = model_name.rstrip('0123456789_')
        try:
            models = os.path.join(rospkg.RosPack().get_path('baxter_sim_examples'), 'models')
        except rospkg.ResourceNotFound as error:
            raise ValueError('no model_path and no baxter_sim_examples: %s' % error)
        return os.path.join(models, self.MODEL_FILES.get(kind, kind + '/model.urdf'))

    def call(self, service_name, service_type, *arguments, **fields):
        rospy.wait_for_service(service_name, self.SERVICE_TIMEOUT)
        return rospy.ServiceProxy(service_name, service_type)(*arguments, **fields)

    def run(self, userdata, model_name, model_path, pose, reference_frame):
        path = model_path or self.model_file(model_name)
        with open(path) as model_file:
            model_xml = model_file.read()
        self.call('/gazebo/delete_model', DeleteModel, model_name)
        kind = 'sdf' if path.endswith('.sdf') else 'urdf'
        response = self.call('/gazebo/spawn_%s_model' % kind, SpawnModel,
                             model_name=model_name, model_xml=model_xml, robot_namespace='/',
                             initial_pose=baxter_pose_msg(pose),
                             reference_frame=self.FRAMES.get(reference_frame, reference_frame))
        if not response.success:
            rospy.logerr('%s: %s', type(self).__name__, response.status_message)
        return 'succeeded' if response.success else 'aborted'
{%- endset %}
{%- do definitions.append(definition) %}
{%- do defined_headers.append('class_LoadGazeboModelState') %}
{%- endif %}
{{ join_definitions(definitions) }}
{%- endblock class_defs %}

{% block body %}
{%- set arguments = [text_argument('model_name', model_name)] %}
{%- set keys = [] %}
{%- if model_path is defined %}{% do arguments.append(text_argument('model_path', model_path)) %}{% endif %}
{%- if pose is defined %}{% do arguments.append(data_argument('pose', pose)) %}{% else %}{% do keys.append('pose') %}{% endif %}
{%- if reference_frame is defined %}{% do arguments.append(text_argument('reference_frame', reference_frame)) %}
{%- elif remapping is defined and 'reference_frame' in remapping %}{% do keys.append('reference_frame') %}{% endif %}
{%- if include_comments %}
# {{ name | pycomment }} ({{ class_name }})
{%- endif %}
{{ render_baxter_state(parent_type, name, 'LoadGazeboModelState', arguments, keys, transitions, remapping) }}
{% endblock body %}
